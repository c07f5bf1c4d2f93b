"""The command line's entry points in process: ``run`` on a JSON document and any other
command (``verify``, ``report convergence``) on its arguments."""

from __future__ import annotations

import json
import re
from typing import List, Optional, Union

from ._numbers import exact_tree
from ._trajverify import TrajverifyError
from ._trajverify import command as _command
from ._trajverify import run as _run


def _in_python_words(error: TrajverifyError) -> TrajverifyError:
    """The command line's refusal with its option names as the keyword arguments' names
    ("option --scalar: …" → "scalar: …")."""
    return TrajverifyError(re.sub(r"option --([a-z-]+)", lambda m: m.group(1).replace("-", "_"), str(error)))


def run(algorithm: str, input: Union[dict, str], scalar: Optional[str] = None) -> dict:
    """The output of ``trajverify run <algorithm> [--scalar <scalar>]`` on `input` (a dict,
    whose numbers are read exactly, or a JSON document), as a dict: the same JSON, byte for
    byte, as the command line prints (see ``docs/commands.md`` for every algorithm).

    >>> run("hermite", {"start": [0, 1], "end": [1, 1], "interval": [0, 1]}, "rational")["control_points"]
    ['0', '1/3', '2/3', '1']
    """
    text = input if isinstance(input, str) else json.dumps(exact_tree(input, ""))
    try:
        return json.loads(_run(algorithm, text, scalar))
    except TrajverifyError as e:
        raise _in_python_words(e) from None


def command(args: List[str]) -> str:
    """Run ``trajverify <args>`` in process (the GIL released) and return what it prints."""
    try:
        return _command([str(a) for a in args])
    except TrajverifyError as e:
        raise _in_python_words(e) from None
