"""A minimal well-behaved IUT for fclcert's harness tests; each fake overrides one thing.

It does not evaluate FCL: load reports the function block names, eval returns
{"sum": <sum of the inputs>, "evals": <evaluations so far in this process>}.
"""
import json
import re
import sys


class FakeIut:
    name = "fake"

    def __init__(self):
        self.evals = 0
        self.blocks = []

    def op_hello(self, req):
        return {"ok": True, "implementation": {"name": self.name, "version": "1.0",
                                               "claims": ["B-FB"], "limits": {"max-points-per-input-term": 3}}}

    def op_load(self, req):
        self.blocks = re.findall(r"\bFUNCTION_BLOCK\s+(\w+)", req["fcl"], re.IGNORECASE)
        return {"ok": True, "blocks": self.blocks}

    def op_eval(self, req):
        self.evals += 1
        return {"ok": True, "outputs": {"sum": float(sum(req["inputs"].values())), "evals": self.evals}}

    def op_reset(self, req):
        return {"ok": True}

    def op_export(self, req):
        return {"ok": False, "error": {"kind": "unsupported"}}

    def op_bye(self, req):
        return {"ok": True}

    def send(self, req, body):
        body["id"] = req.get("id")
        sys.stdout.write(json.dumps(body) + "\n")
        sys.stdout.flush()

    def run(self):
        for line in sys.stdin:
            req = json.loads(line)
            body = getattr(self, "op_" + req["op"])(req)
            if body is not None:
                self.send(req, body)
            if req["op"] == "bye":
                return
