"""Takes a second to start (like a JVM or a big interpreter), then behaves."""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fakebase import FakeIut

time.sleep(1.0)
FakeIut().run()
