"""A legal but slow IUT: answers like fakebase (sum = a + b), but every request except hello and bye only
after DELAY seconds (default 0.85: just within a 1 s timeout). With PIDFILE it appends its own pid and that of
a child it starts (sleep 300, in its process tree) to that file, so a test can check that none survives.

    slow.py [DELAY [PIDFILE]]
"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

DELAY = float(sys.argv[1]) if len(sys.argv) > 1 else 0.85
PIDS = sys.argv[2] if len(sys.argv) > 2 else None


class Slow(FakeIut):
    name = "slow"

    def __init__(self):
        super().__init__()
        if PIDS:
            child = subprocess.Popen(["sleep", "300"], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL)
            with open(PIDS, "a") as f:
                f.write("%d\n%d\n" % (os.getpid(), child.pid))

    def send(self, req, body):
        if req["op"] not in ("hello", "bye"):
            time.sleep(DELAY)
        super().send(req, body)


Slow().run()
