"""Behaves until the fifth eval of a process, then says why on stderr and exits with code 3."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut


class CrashOnFifthEval(FakeIut):
    def op_eval(self, req):
        if self.evals == 4:
            sys.stderr.write("fatal: fifth evaluation, giving up\n")
            sys.stderr.flush()
            sys.exit(3)
        return super().op_eval(req)


CrashOnFifthEval().run()
