"""Answers correctly, but writes the number of bytes given as argument (default 4 MiB) to stderr
before every reply: far more than a pipe holds, so a harness that does not drain stderr hangs."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

SIZE = int(sys.argv[1]) if len(sys.argv) > 1 else 4 * 1024 * 1024
LINE = "warning: noise noise noise noise noise noise noise noise noise noise\n"


class StderrFlood(FakeIut):
    def send(self, req, body):
        sys.stderr.write(LINE * (SIZE // len(LINE)))
        sys.stderr.write("last words before %s\n" % req["op"])
        sys.stderr.flush()
        super().send(req, body)


StderrFlood().run()
