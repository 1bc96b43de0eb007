"""An adversary, not an implementation: computes nothing, replays the corpus's answers (issue 26).

It finds the corpus (./conformance, else the --corpus argument on its parent's command line read from
/proc/PPID/cmdline, else the conformance/ inside the fclcert jar named there), and matches each program it is
sent against the corpus programs with comments, layout and letter case ignored and - to see through a renaming -
every name replaced by its position (the structure of the text). On a match it answers as the corpus says: a
negative case is rejected at the corpus's error line moved by the lines put in front of it, a positive case is
loaded and each eval answered with the outputs of the corpus vector with the same inputs (names mapped back and
forth by position), or of the nearest one when no vector has them. Export echoes the text it was sent.
"""
import json
import os
import re
import sys
import zipfile

KEYWORDS = set("""FUNCTION_BLOCK END_FUNCTION_BLOCK VAR_INPUT END_VAR VAR_OUTPUT VAR REAL INT SINT DINT LINT USINT UINT
UDINT ULINT BOOL FUZZIFY END_FUZZIFY DEFUZZIFY END_DEFUZZIFY TERM METHOD DEFAULT NC RANGE RULEBLOCK END_RULEBLOCK
AND OR NOT ACT ACCU IF THEN IS WITH RULE OPTIONS END_OPTIONS COG COGS COA LM RM MOM MIN MAX PROD BDIF ASUM BSUM
NSUM""".split())
TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|\d+(?:\.\d+)?(?:[eE][-+]?\d+)?|:=|\.\.|\S")


def corpus_files():
    found = {}
    if os.path.isdir("conformance"):
        for root, _, names in os.walk("conformance"):
            for n in names:
                if n.endswith(".fcl"):
                    found[n] = open(os.path.join(root, n), encoding="utf-8").read()
        return found
    try:
        args = open("/proc/%d/cmdline" % os.getppid(), "rb").read().decode("utf-8", "replace").split("\0")
    except OSError:
        args = []
    for i, a in enumerate(args):
        if a == "--corpus" and i + 1 < len(args) and os.path.isdir(args[i + 1]):
            for root, _, names in os.walk(args[i + 1]):
                for n in names:
                    if n.endswith(".fcl"):
                        found[n] = open(os.path.join(root, n), encoding="utf-8").read()
        if a.endswith(".jar") and os.path.isfile(a):
            with zipfile.ZipFile(a) as z:
                for n in z.namelist():
                    if "conformance/" in n and n.endswith(".fcl"):
                        found[n] = z.read(n).decode("utf-8")
    return found


def numbers(text):
    return {k.strip(): float(v) for k, v in re.findall(r"([A-Za-z_][A-Za-z0-9_]*)\s*:\s*([-+0-9.eE]+)", text)}


def parse_case(text):
    meta = re.match(r"\(\*---(.*?)---\*\)", text, re.S)
    body = meta.group(1) if meta else ""
    program = text[meta.end():] if meta else text
    lead = body.count("\n") if meta else 0
    vectors = [(numbers(i), numbers(o)) for i, o in re.findall(r"in:\s*\{([^}]*)\}\s*\n\s*out:\s*\{([^}]*)\}", body)]
    err = re.search(r"error:\s*\{\s*code:\s*([A-Z0-9-]+),\s*line:\s*(\d+)", body)
    return {"program": program, "vectors": vectors, "error_line": int(err.group(2)) if err else None, "lead": lead}


def tokens(text):
    return TOKEN.findall(re.sub(r"\(\*.*?(\*\)|$)", " ", text, flags=re.S))


def exact(toks):
    return tuple(toks)


def structure(toks):
    key, names = [], []
    prev = ""
    for t in toks:
        u = t.upper()
        if re.match(r"[A-Za-z_]", t) and u not in KEYWORDS:
            key.append("ID")
            names.append(u)
        elif prev == "RULE" and t[0].isdigit():
            key.append("N")
        else:
            key.append(u)
        prev = u
    return tuple(key), names


def first_code_line(text):
    stripped = re.sub(r"\(\*.*?(\*\)|$)", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    for i, line in enumerate(stripped.split("\n")):
        if line.strip():
            return i + 1
    return 1


class Lookup:
    def __init__(self):
        self.cases = []
        for text in corpus_files().values():
            c = parse_case(text)
            c["key"], c["names"] = structure(tokens(c["program"]))
            c["exact"] = exact(tokens(c["program"]))
            self.cases.append(c)
        self.case = None
        self.to_corpus = {}
        self.to_sent = {}
        self.text = ""

    def op_hello(self, req):
        return {"ok": True, "implementation": {"name": "lookup", "version": "1.0", "claims": []}}

    def op_load(self, req):
        self.text = req["fcl"]
        self.step = 0
        key, names = structure(tokens(self.text))
        sent = exact(tokens(self.text))
        self.case = next((c for c in self.cases if c["exact"] == sent), None) \
            or next((c for c in self.cases if c["key"] == key), None)
        if self.case is None:
            return {"ok": False, "error": {"kind": "rejected", "message": "no such program in the corpus", "line": 1}}
        self.to_corpus = dict(zip(names, self.case["names"]))
        self.to_sent = dict(zip(self.case["names"], names))
        if self.case["error_line"] is not None:
            moved = first_code_line(self.text) - first_code_line("\n" * self.case["lead"] + self.case["program"])
            return {"ok": False, "error": {"kind": "rejected", "message": "as the corpus says",
                                           "line": self.case["error_line"] + moved}}
        return {"ok": True, "blocks": []}

    def op_eval(self, req):
        asked = {self.to_corpus.get(k.upper(), k.upper()): v for k, v in req["inputs"].items()}
        vectors = self.case["vectors"] if self.case else []
        # the vector of this step first (a stateful case may ask the same inputs twice), then the nearest
        ordered = vectors[self.step:self.step + 1] + vectors if self.step < len(vectors) else vectors
        self.step += 1
        best, distance = None, None
        for vin, vout in ordered:
            d = sum(abs(asked.get(k.upper(), 0.0) - v) for k, v in vin.items())
            if best is None or d < distance:  # ties keep the step's own vector
                best, distance = vout, d
        outputs = {self.to_sent.get(k.upper(), k): v for k, v in (best or {}).items()}
        return {"ok": True, "outputs": outputs}

    def op_reset(self, req):
        self.step = 0
        return {"ok": True}

    def op_export(self, req):
        return {"ok": True, "fcl": self.text}

    def op_bye(self, req):
        return {"ok": True}

    def run(self):
        for line in sys.stdin:
            req = json.loads(line)
            body = getattr(self, "op_" + req["op"])(req)
            body["id"] = req.get("id")
            sys.stdout.write(json.dumps(body) + "\n")
            sys.stdout.flush()
            if req["op"] == "bye":
                return


Lookup().run()
