"""What the Python tests share: the command line to compare against, and exact texts."""

import json
import os
import subprocess
from decimal import Decimal
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
CLI = Path(os.environ.get("TRAJVERIFY_BIN", REPO / "target" / "release" / "trajverify"))
needs_cli = pytest.mark.skipif(not CLI.exists(), reason=f"the command line is not built ({CLI}): cargo build --release")


def cli(algorithm, doc, scalar=None):
    """The command line's output for `doc` (numbers as exact decimal strings)."""
    args = [str(CLI), "run", algorithm] + (["--scalar", scalar] if scalar else [])
    done = subprocess.run(args, input=json.dumps(doc), capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def exact(x):
    """A double's exact decimal expansion, which the command line reads exactly."""
    return str(Decimal(float(x)))
