"""Behaves, but kills itself with SIGSEGV on every K-th request after hello (K from argv): requests K, 2K, ... of
each process, so after a restart the count starts again. Writes a line to stderr first."""
import os
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

EVERY = int(sys.argv[1])


class CrashEvery(FakeIut):
    requests = 0

    def count(self):
        self.requests += 1
        if self.requests % EVERY == 0:
            sys.stderr.write("about to crash on request %d\n" % self.requests)
            sys.stderr.flush()
            os.kill(os.getpid(), signal.SIGSEGV)

    def op_load(self, req):
        self.count()
        return super().op_load(req)

    def op_eval(self, req):
        self.count()
        return super().op_eval(req)

    def op_reset(self, req):
        self.count()
        return super().op_reset(req)

    def op_export(self, req):
        self.count()
        return super().op_export(req)


CrashEvery().run()
