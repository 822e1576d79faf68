"""Waiting on a running program from a test (no fixed sleeps)."""


def read_until_stepping(p):
    """Reads p's stdout until its progress line shows a step (its signal handlers are installed by then) and
    returns what it read; empty or partial if the program ends first."""
    head = ""
    while " step " not in head:
        line = p.stdout.readline()
        head += line
        if not line:
            break
    return head
