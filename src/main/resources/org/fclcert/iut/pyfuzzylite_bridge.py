"""fclcert's bridge to pyfuzzylite: speaks fclcert's JSON-lines protocol (docs/iut-protocol.md) on stdin/stdout.

pyfuzzylite reads only fuzzylite's FLL, so `load` takes FLL text (fclcert presents a case as FLL with its FLL
writer); anything else is whatever pyfuzzylite's FllImporter makes of it. One engine is one function block.
Started by org.fclcert.iut.PyfuzzyliteIut as `PYTHON pyfuzzylite_bridge.py`, inside fclcert's sandbox.
"""
import json
import re
import sys
import time

try:
    import fuzzylite as fl
except Exception as e:  # no pyfuzzylite: hello fails, and the run says why
    fl = None
    IMPORT_ERROR = f"{type(e).__name__}: {e}"

# Python exceptions that are a library's bug rather than its refusal: answered with kind 'crash'
INTERNAL = (RecursionError, MemoryError, AttributeError, TypeError, IndexError, ZeroDivisionError, AssertionError)

text = None
engine = None


def reply(message, request):
    if "id" in request:
        message["id"] = request["id"]
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def failure(kind, message, line=None):
    error = {"kind": kind, "message": message}
    if line is not None:
        error["line"] = line
    return {"ok": False, "error": error}


def describe(e):
    return f"{type(e).__name__}: {e}".strip()


def quoted_line(message, source):
    """The 1-based line of `source` that pyfuzzylite's message quotes ('...'), if any: its messages name no line."""
    for fragment in re.findall(r"'([^'\n]{3,})'", message):
        for number, line in enumerate(source.splitlines(), start=1):
            if fragment.strip() and fragment.strip() in line:
                return number
    return None


def fresh():
    """A new engine from the loaded text, every input at 0 (a REAL's initial value; pyfuzzylite starts at NaN)."""
    e = fl.FllImporter().from_string(text)
    for v in e.input_variables:
        v.value = 0.0
    return e


def load(request):
    global text, engine
    text, engine = None, None
    source = request.get("fcl", "")
    try:
        text = source
        e = fresh()
    except INTERNAL as x:
        text = None
        return failure("crash", "pyfuzzylite failed while importing: " + describe(x))
    except Exception as x:
        text = None
        return failure("rejected", "pyfuzzylite's FllImporter: " + describe(x), quoted_line(str(x), source))
    engine = e
    return {"ok": True, "blocks": [e.name or "engine"]}


def evaluate(request):
    if engine is None:
        return failure("error", "no program loaded")
    block = request.get("block")
    if block is not None and block.lower() != (engine.name or "engine").lower():
        return failure("error", f"pyfuzzylite holds one engine, '{engine.name}'; '{block}' is not it")
    inputs = {v.name.lower(): v for v in engine.input_variables}
    for name, value in request.get("inputs", {}).items():
        v = inputs.get(name.lower())
        if v is None:
            return failure("error", f"{name} is not an input of {engine.name}")
        v.value = float(value)
    start = time.perf_counter()
    try:
        engine.process()
    except INTERNAL as x:
        return failure("crash", "pyfuzzylite failed while processing: " + describe(x))
    except Exception as x:
        return failure("error", "pyfuzzylite: " + describe(x))
    elapsed = (time.perf_counter() - start) * 1000.0
    # pyfuzzylite keeps values as NumPy scalars or one-element arrays
    outputs = {v.name: float(v.value.item() if hasattr(v.value, "item") else v.value) for v in engine.output_variables}
    return {"ok": True, "outputs": outputs, "elapsedMs": elapsed}


def reset(request):
    global engine
    if text is None:
        return failure("error", "no program loaded")
    try:
        engine = fresh()
    except Exception as x:
        return failure("crash", "pyfuzzylite failed to import the program again: " + describe(x))
    return {"ok": True}


def main():
    for raw in sys.stdin:
        raw = raw.strip()
        if not raw:
            continue
        request = json.loads(raw)
        op = request.get("op")
        if op == "hello":
            if fl is None:
                sys.stderr.write("pyfuzzylite is not installed: " + IMPORT_ERROR + "\n")
                sys.stderr.flush()
                return 3
            reply({"ok": True, "implementation": {"name": "pyfuzzylite", "version": fl.__version__,
                                                  "claims": []}}, request)
        elif op == "load":
            reply(load(request), request)
        elif op == "eval":
            reply(evaluate(request), request)
        elif op == "reset":
            reply(reset(request), request)
        elif op == "export":
            # pyfuzzylite writes FLL and Python, not FCL
            reply({"ok": False, "error": {"kind": "unsupported"}}, request)
        elif op == "bye":
            reply({"ok": True}, request)
            return 0
        else:
            reply(failure("error", f"unknown op {op!r}"), request)
    return 0


if __name__ == "__main__":
    sys.exit(main())
