"""A hostile IUT: greets, loads and evaluates like fakebase (sum = a + b), but attacks fclcert in the way
named by its argument:

  deep-export     exports the loaded program with its first condition wrapped 1000 times in NOT (c AND a IS on)
  surrogate-name  names itself with a lone UTF-16 surrogate (valid JSON: "\\udc00")
  surrogate-msg   rejects every program with a message holding a lone surrogate
  huge-msg        rejects every program with a 1 MB message
  dup-key         answers eval with {"sum": 12345, "sum": <right>} (a key twice)
  case-key        answers eval with {"sum": <right>, "SUM": 12345} (keys equal but for case)
  inject          a name, version and rejection message full of terminal and Markdown/HTML injections
  no-fcl-export   answers export with ok:true but no 'fcl'
  unasked         writes an extra eval reply right after each load reply, before being asked
  orphan FILE     at hello starts a child (its pid appended to FILE) that keeps stdout open; at the first eval
                  the IUT itself exits without a reply, so stdout stays open and the child is re-parented
  name TEXT       names itself TEXT (say 'reference', or 300 characters: the default output directory's name)
  escape CHECKOUT OUT CORPUS REALHOME PORT MARKER
                  at hello tries to write into the checkout and the output directory, lists its home and the real
                  home, looks for the corpus, connects to 127.0.0.1:PORT (a listener of the test's own, never
                  anywhere else), and leaves a double-forked setsid child (its argv[0] MARKER) that appends to
                  OUT/report.md a few seconds later; what it saw is its version string
  burst N         at the first eval starts N sleeping processes (a bounded burst, never a fork bomb)
  write-gb        at the first eval writes 1 GB to a file in its working directory
  jitter          a correct implementation with noise: each eval's outputs times 1 + 1e-12 or 1 - 1e-12 in turn
  bom             a UTF-8 byte-order mark before its reply to hello
"""
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

MODE = sys.argv[1] if len(sys.argv) > 1 else "deep-export"
INJECT = ("evil\r\x1b[2K\x1b]0;pwned\x07FAILED\n# forged heading\n**Basic Level: conformant**"
          " <script>alert(1)</script> [click](javascript:alert(1)) \x00nul")


def attempt(action):
    """'ok' or the name of the error the action raised."""
    try:
        action()
        return "ok"
    except Exception as e:  # noqa: BLE001 - any refusal is an answer here
        return type(e).__name__


def escape(checkout, out, corpus, real_home, port, marker):
    import socket

    def write(path):
        with open(path, "a") as f:
            f.write("written by the implementation\n")

    def connect():
        s = socket.create_connection(("127.0.0.1", int(port)), timeout=2)
        s.sendall(b"hello from the implementation\n")
        s.close()

    def listing(path):
        try:
            return ",".join(sorted(os.listdir(path)))
        except OSError as e:
            return type(e).__name__

    seen = {
        "checkout": attempt(lambda: write(os.path.join(checkout, "written-by-iut.txt"))),
        "out": attempt(lambda: write(os.path.join(out, "written-by-iut.txt"))),
        "home": listing(os.path.expanduser("~")),
        "realhome": listing(real_home),
        "corpus": "present" if os.path.exists(corpus) else "absent",
        "connect": attempt(connect),
        "m2": "present" if os.path.exists(os.path.join(real_home, ".m2")) else "absent",
    }
    if os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            forger = "sleep 3; echo FORGED >> '%s'" % os.path.join(out, "report.md")
            os.execv("/bin/sh", [marker, "-c", forger])
        os._exit(0)
    os.wait()
    return ";".join("%s=%s" % kv for kv in seen.items())


def burst(n):
    import time
    for _ in range(n):
        if os.fork() == 0:
            time.sleep(60)
            os._exit(0)


class Hostile(FakeIut):
    program = ""

    def op_hello(self, req):
        body = super().op_hello(req)
        if MODE == "surrogate-name":
            body["implementation"]["name"] = "sur\udc00rogate"
        if MODE == "orphan":
            import subprocess
            child = subprocess.Popen(["sleep", "60"], stdin=subprocess.DEVNULL)   # inherits stdout
            with open(sys.argv[2], "a") as f:
                f.write("%d\n" % child.pid)
        if MODE == "name":
            body["implementation"]["name"] = sys.argv[2]
        if MODE == "escape":
            body["implementation"]["version"] = escape(*sys.argv[2:8])
        if MODE == "inject":
            body["implementation"]["name"] = INJECT
            body["implementation"]["version"] = "1.0\x1b[31m"
        return body

    def op_load(self, req):
        self.program = req["fcl"]
        reject = {"surrogate-msg": "bad \udc00 program", "huge-msg": "x" * 1_000_000, "inject": INJECT}
        if MODE in reject:
            return {"ok": False, "error": {"kind": "rejected", "message": reject[MODE], "line": 1}}
        return super().op_load(req)

    def op_eval(self, req):
        if MODE == "orphan":
            os._exit(0)
        if MODE == "burst" and self.evals == 0:
            burst(int(sys.argv[2]))
        if MODE == "write-gb" and self.evals == 0:
            with open("big.bin", "wb") as f:
                chunk = b"x" * (1 << 20)
                for _ in range(1024):
                    f.write(chunk)
        body = super().op_eval(req)
        right = body["outputs"]["sum"]
        if MODE == "jitter":
            body["outputs"]["sum"] = right * (1 + (1e-12 if self.evals % 2 else -1e-12))
        if MODE == "dup-key":
            return '{"ok": true, "outputs": {"sum": 12345, "sum": %r}, "id": %d}' % (right, req["id"])
        if MODE == "case-key":
            return '{"ok": true, "outputs": {"sum": %r, "SUM": 12345}, "id": %d}' % (right, req["id"])
        return body

    def op_export(self, req):
        if MODE == "deep-export":
            m = re.search(r"\bIF\s+(.*?)\s+THEN\b", self.program)
            c = m.group(1)
            for _ in range(1000):
                c = "NOT (" + c + " AND a IS on)"
            fcl = self.program[:m.start(1)] + c + self.program[m.end(1):]
            return {"ok": True, "fcl": re.sub(r"ACCU\s*:\s*MAX;", "AND : MIN; ACCU : MAX;", fcl, count=1)}
        if MODE == "no-fcl-export":
            return {"ok": True}
        return super().op_export(req)

    def send(self, req, body):
        if MODE == "bom" and req["op"] == "hello":
            sys.stdout.write("\ufeff" + json.dumps(dict(body, id=req["id"])) + "\n")
            sys.stdout.flush()
            return
        if isinstance(body, str):
            sys.stdout.write(body + "\n")
            sys.stdout.flush()
            return
        if MODE == "unasked" and req["op"] == "load":
            # the load reply and an eval reply nobody asked for in one write, so that both reach fclcert together
            extra = json.dumps({"ok": True, "outputs": {"sum": 3.0}})
            sys.stdout.write(json.dumps(dict(body, id=req["id"])) + "\n" + extra + "\n")
            sys.stdout.flush()
            return
        super().send(req, body)


Hostile().run()
