"""Greets correctly, then answers every other request wrongly in the way named by its argument:

  text      a line that is not JSON
  wrong-id  a correct reply with another request's id
  no-ok     a JSON object without the boolean 'ok'
  array     a JSON array
  trailing  a correct reply followed by more text on the same line
  bad-shape an eval reply whose outputs are strings
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

MODE = sys.argv[1] if len(sys.argv) > 1 else "text"


class Garbage(FakeIut):
    def send(self, req, body):
        if req["op"] == "hello":
            return super().send(req, body)
        body["id"] = req.get("id")
        if MODE == "text":
            line = "Result: all fine, thank you"
        elif MODE == "wrong-id":
            body["id"] = (req.get("id") or 0) + 1000
            line = json.dumps(body)
        elif MODE == "no-ok":
            del body["ok"]
            line = json.dumps(body)
        elif MODE == "array":
            line = json.dumps([body])
        elif MODE == "trailing":
            line = json.dumps(body) + " and more"
        else:
            body["outputs"] = {"sum": "twelve"}
            line = json.dumps(body)
        sys.stdout.write(line + "\n")
        sys.stdout.flush()


Garbage().run()
