"""Greets, then hangs on load after starting a child process that would also hang.

The child's pid goes to stderr so a test can check that killing the IUT killed its children too.
"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut


class HangOnLoad(FakeIut):
    def op_load(self, req):
        child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
        sys.stderr.write("child pid %d\n" % child.pid)
        sys.stderr.flush()
        time.sleep(600)


HangOnLoad().run()
