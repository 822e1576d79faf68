#!/usr/bin/env python3
"""lcpbench -help documents every named choice from its registry: for -family, -solvers and -fclib_model,
the help lists exactly the names that the option accepts (read off the one error for an unknown value, which
is generated from the same registry), each with a one-line description.

Usage: test_lcpbench_help.py LCPBENCH
"""
import os
import re
import subprocess
import sys
import tempfile

OPTIONS = ["-family", "-solvers", "-fclib_model"]


def run(exe, *args, cwd):
    p = subprocess.run([exe, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=cwd, timeout=60)
    return p.returncode, p.stdout.decode(errors="replace")


def known_names(exe, option, cwd):
    """The accepted names, from the error message 'Unknown OPTION 'x': a, b or c'."""
    rc, out = run(exe, option, "no_such_choice", "-output", "x.h5", cwd=cwd)
    m = re.search(re.escape(f"Unknown {option} 'no_such_choice': ") + r"(.*)$", out, re.M)
    if rc == 0 or not m:
        sys.exit(f"FAIL: {option} no_such_choice was not refused with the list of names:\n{out}")
    return re.split(r", | or ", m.group(1).strip())


def help_choices(help_text, option):
    """Name -> description of the indented lines that follow the option's own line in -help."""
    lines = help_text.splitlines()
    start = next((i for i, l in enumerate(lines) if l.strip().startswith(option + " ")), None)
    if start is None:
        sys.exit(f"FAIL: {option} not in -help")
    choices = {}
    for line in lines[start + 1:]:
        m = re.match(r"^      (\S+)  +(\S.*)$", line)
        if not m:
            break
        choices[m.group(1)] = m.group(2)
    return choices


def main():
    exe = sys.argv[1]
    with tempfile.TemporaryDirectory() as d:
        rc, help_text = run(exe, "-help", cwd=d)
        if rc != 0:
            sys.exit(f"FAIL: -help exited {rc}:\n{help_text}")
        failed = False
        for option in OPTIONS:
            names = known_names(exe, option, d)
            listed = help_choices(help_text, option)
            if list(listed) != names:
                print(f"FAIL: -help lists {list(listed)} for {option}, the option accepts {names}")
                failed = True
            for name, text in listed.items():
                if len(text.strip()) < 10:
                    print(f"FAIL: {option} {name}: description '{text}' too short")
                    failed = True
            print(f"{option}: {len(names)} choices documented: {', '.join(names)}")
        if len(known_names(exe, "-solvers", d)) < 8:
            print("FAIL: fewer than 8 solvers registered")
            failed = True
        sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
