"""The Basic Level example IUT (examples/iut/basic_iut.py), except that a program of 1000 or more rules
makes it die at load: it writes why on stderr and exits with code 9, without answering."""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "..", "examples", "iut"))
import basic_iut  # noqa: E402


class CrashingSession(basic_iut.Session):
    def load(self, req):
        if len(re.findall(r"\bRULE\s+\w+\s*:", req["fcl"], re.IGNORECASE)) >= 1000:
            sys.stderr.write("fatal: rule table overflow\n")
            sys.stderr.flush()
            os._exit(9)
        return super().load(req)


basic_iut.Session = CrashingSession
basic_iut.main()
