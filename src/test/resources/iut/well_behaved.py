"""Answers every request correctly (see fakebase.py)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

FakeIut().run()
