"""Runs a test's command with a timeout: what tests/expect_failure.py and tests/expect_output.py share."""
import subprocess


def run_command(argv, timeout):
    """Runs the command in argv (after an optional '--'); prints and returns (exit status, stdout and stderr
    together), or prints a FAIL line with the output so far and returns None when it runs past timeout s."""
    cmd = argv[1:] if argv and argv[0] == "--" else argv
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        print(f"FAIL: command hung (> {timeout} s): {' '.join(cmd)}")
        print((e.stdout or b"").decode(errors="replace"))
        return None
    out = p.stdout.decode(errors="replace")
    print(out)
    return p.returncode, out


def verdict(failures, ok_message):
    """Prints each failure as a FAIL line, or ok_message as the OK line when there is none; the exit status."""
    for f in failures:
        print(f"FAIL: {f}")
    if not failures:
        print(f"OK: {ok_message}")
    return 1 if failures else 0
