#!/usr/bin/env python3
"""basic_iut.py - a small FCL implementation that fclcert can certify as a separate process.

It realises the Basic Level of IEC 61131-7 (Table 8) and one extension, a constant WITH (so that
the example of clause 5.3 runs): VAR_INPUT/VAR_OUTPUT of type REAL, LREAL or an integer type
(integer inputs and outputs rounded half away from zero), input terms of at most three constant points,
singleton output terms, AND with MIN, ACCU with MAX, METHOD CoGS, DEFAULT with a value or NC, one
rule block, rules 'IF v IS t AND ... THEN v IS t [WITH w];'. Anything else is rejected with the
line where it starts.

It speaks fclcert's JSON-lines protocol (docs/iut-protocol.md): one request per line on stdin,
one reply per line on stdout. Try it:
    fclcert certify --iut 'process:python3 examples/iut/basic_iut.py' --level basic
"""
import json
import math
import re
import sys

CLAIMS = ["B-FB", "B-IN-TERM", "B-OUT-SINGLETON", "B-AND-MIN", "B-ACCU-MAX", "B-COGS",
          "B-DEFAULT-VALUE", "B-DEFAULT-NC", "B-ONE-RULEBLOCK", "B-SUBCONDITIONS",
          "B-ONE-SUBCONCLUSION", "E-WITH-CONST"]

TOKEN = re.compile(r"""(?P<comment>\(\*.*?\*\))|(?P<space>\s+)
    |(?P<number>[+-]?\d[\d_]*(?:\.[\d_]+)?(?:[eE][+-]?[\d_]+)?)
    |(?P<name>[A-Za-z_]\w*)|(?P<punct>:=|[():;,])""", re.S | re.X)
# IEC 61131-3 spelling: single underscores only between digits or letters; an exponent needs a '.'
NUMBER = re.compile(r"[+-]?\d(?:_?\d)*(?:\.\d(?:_?\d)*(?:[eE][+-]?\d(?:_?\d)*)?)?\Z")
IDENTIFIER = re.compile(r"(?:[A-Za-z]|_[A-Za-z0-9])(?:_?[A-Za-z0-9])*\Z")

# keywords of Table 7 and the data type names: none of them may name anything
RESERVED = set("""ACCU ACT AND ASUM BDIF BSUM COA COG COGS DEFAULT DEFUZZIFY END_DEFUZZIFY
    END_FUNCTION_BLOCK END_FUZZIFY END_OPTIONS END_RULEBLOCK END_VAR FUNCTION_BLOCK FUZZIFY IF IS LM
    MAX METHOD MIN NC NOT NSUM OPTIONS OR PROD RANGE RM RULE RULEBLOCK TERM THEN VAR VAR_INPUT
    VAR_OUTPUT WITH REAL LREAL SINT INT DINT LINT USINT UINT UDINT ULINT""".split())


# integer data types (IEC 61131-3) and their ranges; REAL and LREAL are the floating ones
INTEGERS = {"SINT": (-2**7, 2**7 - 1), "INT": (-2**15, 2**15 - 1), "DINT": (-2**31, 2**31 - 1),
            "LINT": (-2**63, 2**63 - 1), "USINT": (0, 2**8 - 1), "UINT": (0, 2**16 - 1),
            "UDINT": (0, 2**32 - 1), "ULINT": (0, 2**64 - 1)}

# what a rule block may declare, and the algorithms accepted (activation does not matter for singletons)
SETTINGS = {"AND": ("MIN",), "ACT": ("MIN", "PROD"), "ACCU": ("MAX",)}


class Reject(Exception):
    """The program is not one this implementation accepts; 'line' is where the problem starts."""

    def __init__(self, message, line):
        super().__init__(message)
        self.message, self.line = message, line


def tokenize(text):
    """(kind, value, line) triples; kind is 'number', 'name', a punctuation mark, 'eof', or 'bad'
    (a message, reported only when the parser gets there, so that earlier errors come first)."""
    tokens, pos, line = [], 0, 1
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:
            what = "comment is never closed" if text.startswith("(*", pos) else "unexpected %r" % text[pos]
            tokens.append(("bad", what, line))
            break
        kind, value = m.lastgroup, m.group()
        if kind == "number":
            good = NUMBER.match(value)
            tokens.append(("number", float(value.replace("_", "")), line) if good
                          else ("bad", "malformed number %r" % value, line))
        elif kind == "name":
            tokens.append(("name", value, line) if IDENTIFIER.match(value)
                          else ("bad", "malformed identifier %r" % value, line))
        elif kind == "punct":
            tokens.append((value, value, line))
        line += value.count("\n")
        pos = m.end()
    tokens.append(("eof", None, line))
    return tokens


class Parser:
    """Recursive descent over the tokens; builds plain dicts keyed by lower-case names."""

    def __init__(self, text):
        self.tokens, self.i = tokenize(text), 0

    def peek(self):
        kind, value, line = self.tokens[self.i]
        if kind == "bad":
            raise Reject(value, line)
        return self.tokens[self.i]

    def line(self):
        return self.peek()[2]

    def take(self):
        token = self.peek()
        self.i += 1
        return token

    def at(self, *words):
        kind, value, _ = self.peek()
        return kind == "name" and value.upper() in words or kind in words

    def fail(self, what):
        kind, value, line = self.peek()
        if what == ";" and self.i > 0 and self.tokens[self.i - 1][2] < line:
            line = self.tokens[self.i - 1][2]   # a missing ';' is the mistake of the line that lacks it
        raise Reject("expected %s, found %s" % (what, "end of text" if kind == "eof" else repr(value)), line)

    def expect(self, word):
        if not self.at(word):
            self.fail(word)
        return self.take()

    def name(self):
        if self.peek()[0] != "name":
            self.fail("a name")
        if self.peek()[1].upper() in RESERVED:
            raise Reject("%s is a keyword and cannot be used as a name" % self.peek()[1], self.line())
        return self.take()[1]

    def number(self):
        if self.peek()[0] != "number":
            self.fail("a number")
        return self.take()[1]

    def unsupported(self, what=None):
        raise Reject("%s is not supported at the Basic Level" % (what or repr(self.peek()[1])), self.line())

    def program(self):
        if self.at("eof"):
            raise Reject("the text holds no FUNCTION_BLOCK", 1)
        blocks = [self.block()]
        while not self.at("eof"):
            blocks.append(self.block())
        return blocks

    def block(self):
        self.expect("FUNCTION_BLOCK")
        fb = {"name": self.name(), "inputs": {}, "outputs": {}, "fuzzify": {}, "defuzzify": {}, "rules": None}
        sections = {"VAR_INPUT": self.variables, "VAR_OUTPUT": self.variables, "FUZZIFY": self.fuzzify,
                    "DEFUZZIFY": self.defuzzify, "RULEBLOCK": self.ruleblock}
        order = ["VAR_INPUT", "FUZZIFY", "DEFUZZIFY", "RULEBLOCK"]  # the order 5.4 prescribes
        last = 0
        while not self.at("END_FUNCTION_BLOCK"):
            keyword = str(self.peek()[1]).upper()
            if keyword not in sections:
                self.fail("END_FUNCTION_BLOCK") if self.at("eof") else self.unsupported()
            rank = order.index(keyword.replace("VAR_OUTPUT", "VAR_INPUT"))
            if rank < last:
                raise Reject("%s must come before %s" % (keyword, order[last]), self.line())
            last = rank
            sections[keyword](fb)
        self.take()
        resolve(fb)
        return fb

    def variables(self, fb):
        table = fb["inputs"] if self.take()[1].upper() == "VAR_INPUT" else fb["outputs"]
        while not self.at("END_VAR"):
            line, names = self.line(), [self.name()]
            while self.at(","):
                self.take()
                names.append(self.name())
            self.expect(":")
            if not self.at("REAL", "LREAL", *INTEGERS):
                self.unsupported("data type %r" % self.peek()[1])
            dtype = self.take()[1].upper()
            init = 0.0
            if self.at(":="):
                self.take()
                init = self.number()
            self.expect(";")
            low, high = INTEGERS.get(dtype, (-math.inf, math.inf))
            if not low <= init <= high or dtype in INTEGERS and init != int(init):
                raise Reject("initial value %s does not fit %s" % (init, dtype), line)
            for n in names:
                if n.lower() in fb["inputs"] or n.lower() in fb["outputs"]:
                    raise Reject("variable %s is declared twice" % n, line)
                table[n.lower()] = {"name": n, "init": init, "type": dtype}
        self.take()

    def fuzzify(self, fb):
        self.take()
        line, var = self.line(), self.name().lower()
        if var not in fb["inputs"] or var in fb["fuzzify"]:
            raise Reject("FUZZIFY %s: not a declared input, or fuzzified twice" % var, line)
        terms = fb["fuzzify"][var] = {}
        while self.at("TERM"):
            self.take()
            line, term = self.line(), self.name().lower()
            self.expect(":=")
            points = []
            while self.at("("):
                self.take()
                x = self.number()
                self.expect(",")
                points.append((x, self.number()))
                self.expect(")")
                if self.at(",") and self.tokens[self.i + 1][0] == "(":
                    self.take()  # points may be separated by commas, as in figure 5
            self.expect(";")
            if not 2 <= len(points) <= 3 or any(a[0] > b[0] for a, b in zip(points, points[1:])):
                raise Reject("term %s needs 2 or 3 points in ascending order" % term, line)
            if any(not 0 <= y <= 1 for _, y in points):
                raise Reject("term %s has a degree outside [0, 1]" % term, line)
            if term in terms:
                raise Reject("term %s is defined twice" % term, line)
            terms[term] = points
        self.expect("END_FUZZIFY")

    def defuzzify(self, fb):
        start = self.take()[2]
        line, var = self.line(), self.name().lower()
        if var not in fb["outputs"] or var in fb["defuzzify"]:
            raise Reject("DEFUZZIFY %s: not a declared output, or defuzzified twice" % var, line)
        out = fb["defuzzify"][var] = {"terms": {}, "method": None, "default": None}
        order, last = ["TERM", "METHOD", "DEFAULT"], 0  # terms, then METHOD, then DEFAULT, once each
        while not self.at("END_DEFUZZIFY"):
            line, keyword = self.line(), str(self.take()[1]).upper()
            rank = order.index(keyword) if keyword in order else -1
            if rank >= 0 and (rank < last or rank == last > 0):
                raise Reject("%s is out of place (order: TERMs, METHOD, DEFAULT; once each)" % keyword, line)
            last = max(last, rank)
            if keyword == "TERM":
                line, term = self.line(), self.name().lower()
                if term in out["terms"]:
                    raise Reject("term %s is defined twice" % term, line)
                self.expect(":=")
                out["terms"][term] = self.number()
            elif keyword == "METHOD":
                self.expect(":")
                out["method"] = self.take()[1] if self.at("COGS") else self.unsupported()
            elif keyword == "DEFAULT":
                self.expect(":=")
                out["default"] = self.take()[1] if self.at("NC") else self.number()
            else:
                self.i -= 1
                self.unsupported()
            self.expect(";")
        self.take()
        if out["method"] is None or out["default"] is None:
            raise Reject("DEFUZZIFY %s needs METHOD: CoGS and a DEFAULT" % var, start)

    def ruleblock(self, fb):
        if fb["rules"] is not None:
            self.unsupported("a second RULEBLOCK")
        start = self.take()[2]
        self.name()
        rules, declared, names = [], set(), set()
        fb["rules"] = rules
        order, last = ["AND", "ACT", "ACCU", "RULE"], -1  # operators, ACT, ACCU, then the rules
        while not self.at("END_RULEBLOCK"):
            keyword = str(self.peek()[1]).upper()
            if keyword not in order:
                self.unsupported()
            if order.index(keyword) < last or order.index(keyword) == last < 3:
                raise Reject("%s is out of place (order: AND, ACT, ACCU, rules)" % keyword, self.line())
            last = order.index(keyword)
            if keyword == "RULE":
                rules.append(self.rule(names))
                continue
            self.take()
            self.expect(":")
            if not self.at(*SETTINGS[keyword]):
                self.unsupported()
            self.take()
            self.expect(";")
            declared.add(keyword)
        self.take()
        if "ACCU" not in declared:
            raise Reject("the rule block needs ACCU: MAX", start)
        uses_and = [r["and"] for r in rules if r["and"]]
        if uses_and and "AND" not in declared:
            raise Reject("AND is used but the rule block does not declare AND: MIN", uses_and[0])

    def rule(self, names):
        self.take()
        if self.peek()[0] not in ("name", "number"):
            self.fail("a rule name or number")
        line, name = self.line(), str(self.take()[1]).lower()
        if name in names:
            raise Reject("rule %s is defined twice" % name, line)
        names.add(name)
        self.expect(":")
        self.expect("IF")
        conditions, and_line = [self.subcondition()], None
        while self.at("AND"):
            and_line = and_line or self.line()
            self.take()
            conditions.append(self.subcondition())
        if not self.at("THEN"):
            self.unsupported() if self.at("OR", "NOT", "(") else self.fail("THEN")
        self.take()
        line, var = self.line(), self.name().lower()
        self.expect("IS")
        rule = {"if": conditions, "then": (var, self.name().lower(), line), "with": 1.0, "and": and_line}
        if self.at("WITH"):
            self.take()
            rule["with"] = self.number()
            if not 0 <= rule["with"] <= 1:
                raise Reject("WITH must lie in [0, 1]", line)
        self.unsupported("a second subconclusion") if self.at(",") else self.expect(";")
        return rule

    def subcondition(self):
        if self.at("(", "NOT"):
            self.unsupported()
        line, var = self.line(), self.name().lower()
        self.expect("IS")
        if self.at("NOT"):
            self.unsupported()
        return var, self.name().lower(), line


def resolve(fb):
    """Every subcondition names a fuzzified input's term, every conclusion a defuzzified output's term."""
    for rule in fb["rules"] or []:
        for var, term, line in rule["if"]:
            if term not in fb["fuzzify"].get(var, {}):
                raise Reject("%s IS %s: no such input term" % (var, term), line)
        var, term, line = rule["then"]
        if term not in fb["defuzzify"].get(var, {"terms": {}})["terms"]:
            raise Reject("%s IS %s: no such output term" % (var, term), line)


def membership(points, x):
    """Linear between points, constant beyond the outer ones; at a vertical edge the larger degree."""
    at_x = [y for px, y in points if px == x]
    if at_x:
        return max(at_x)
    if x <= points[0][0]:
        return points[0][1]
    for (x1, y1), (x2, y2) in zip(points, points[1:]):
        if x <= x2:
            return y2 if x2 == x1 else y1 + (y2 - y1) * (x - x1) / (x2 - x1)
    return points[-1][1]


def evaluate(fb, state):
    """MIN over subconditions, times WITH; MAX per output term; CoGS; DEFAULT (or NC) when none fired."""
    degrees = {}
    for rule in fb["rules"] or []:
        d = min(membership(fb["fuzzify"][v][t], state["in"][v]) for v, t, _ in rule["if"]) * rule["with"]
        key = rule["then"][:2]
        degrees[key] = max(degrees.get(key, 0.0), d)
    for var, out in fb["defuzzify"].items():
        fired = [(d, out["terms"][t]) for (v, t), d in degrees.items() if v == var and d > 0]
        if fired:
            state["out"][var] = crisp(fb["outputs"][var], sum(d * x for d, x in fired) / sum(d for d, _ in fired))
        elif not isinstance(out["default"], str):
            state["out"][var] = crisp(fb["outputs"][var], out["default"])  # a DEFAULT value; NC keeps the last one


def crisp(output, value):
    """An integer variable (input or output) gets the value rounded half away from zero, and it must fit its type."""
    if output["type"] not in INTEGERS:
        return value
    rounded = math.floor(abs(value) + 0.5) * (1 if value >= 0 else -1)
    low, high = INTEGERS[output["type"]]
    if not low <= rounded <= high:
        raise ValueError("%s = %s does not fit %s" % (output["name"], rounded, output["type"]))
    return float(rounded)


class Session:
    def __init__(self):
        self.blocks, self.instances = [], {}

    def hello(self, req):
        return {"implementation": {"name": "basic_iut.py", "version": "1.0", "claims": CLAIMS}}

    def load(self, req):
        self.blocks, self.instances = [], {}
        self.blocks = Parser(req["fcl"]).program()
        return {"blocks": [fb["name"] for fb in self.blocks]}

    def eval(self, req):
        if not self.blocks:
            raise ValueError("no program is loaded")
        wanted = (req.get("block") or self.blocks[0]["name"]).lower()
        fb = next((b for b in self.blocks if b["name"].lower() == wanted), None)
        if fb is None:
            raise ValueError("no function block %s" % wanted)
        state = self.instances.setdefault(wanted, {
            "in": {k: v["init"] for k, v in fb["inputs"].items()},
            "out": {k: v["init"] for k, v in fb["outputs"].items()}})
        for name, value in req["inputs"].items():
            if name.lower() not in state["in"]:
                raise ValueError("%s is not an input of %s" % (name, fb["name"]))
            # an integer input takes the value rounded half away from zero, and it must fit its type (8.)
            state["in"][name.lower()] = crisp(fb["inputs"][name.lower()], float(value))
        evaluate(fb, state)
        return {"outputs": {fb["outputs"][k]["name"]: v for k, v in state["out"].items()}}

    def reset(self, req):
        self.instances = {}
        return {}

    def bye(self, req):
        return {}


def answer(session, req):
    op = req.get("op")
    if op == "export":
        return {"ok": False, "error": {"kind": "unsupported"}}
    if op not in ("hello", "load", "eval", "reset", "bye"):
        return {"ok": False, "error": {"kind": "error", "message": "unknown op %r" % op}}
    try:
        return dict(ok=True, **getattr(session, op)(req))
    except Reject as r:
        return {"ok": False, "error": {"kind": "rejected", "message": r.message, "line": r.line}}
    except (ValueError, KeyError, TypeError, AttributeError) as e:
        return {"ok": False, "error": {"kind": "error", "message": str(e)}}


def main():
    session = Session()
    for line in sys.stdin:
        req = json.loads(line)
        reply = answer(session, req)
        if "id" in req:
            reply["id"] = req["id"]
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()
        if req.get("op") == "bye":
            break


if __name__ == "__main__":
    main()
