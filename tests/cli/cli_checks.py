"""What the dclaw checks share: a pass/fail count and running dclaw."""
import os
import subprocess
import sys

counts = {"passed": 0, "failed": 0}


def check(ok, what):
    """Counts one check and prints it if it failed."""
    counts["passed" if ok else "failed"] += 1
    if not ok:
        print("FAIL:", what)


def run(exe, args, env=None, timeout=300):
    """Runs exe with args (and extra environment); returns (exit code, stdout, stderr)."""
    p = subprocess.run([exe] + args, capture_output=True, text=True, timeout=timeout,
                       env=dict(os.environ, **(env or {})))
    return p.returncode, p.stdout, p.stderr


def finish():
    """Prints the count and exits 1 if a check failed."""
    print("%d passed, %d failed" % (counts["passed"], counts["failed"]))
    sys.exit(1 if counts["failed"] else 0)
