"""Answers hello, then stops reading its input for good (so a large request fills the pipe)."""
import json
import sys
import time

req = json.loads(sys.stdin.readline())
sys.stdout.write(json.dumps({"ok": True, "implementation": {"name": "deaf", "version": "0"}, "id": req["id"]}) + "\n")
sys.stdout.flush()
time.sleep(600)
