"""Answers eval with one reply line of the size in bytes given as argument (default 20 MiB)."""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

SIZE = int(sys.argv[1]) if len(sys.argv) > 1 else 20 * 1024 * 1024


class HugeReply(FakeIut):
    def op_eval(self, req):
        body = super().op_eval(req)
        body["padding"] = "x" * SIZE
        return body


HugeReply().run()
