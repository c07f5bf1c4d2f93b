"""The claims ledger (``claims.json``) as Python objects: a dict of the JSON, with typed claims.

Each claim is one checkable statement of a paper: where it is printed, what is printed, what
the library computed, in which number types, how sure that number is (`assurance`: exact,
proven, certified or floating) and the verdict of the project's one written policy
(``docs/papers.md``, "The verdict policy").
"""

from __future__ import annotations

from typing import Dict, Iterator, List, NamedTuple, Optional


class Claim(NamedTuple):
    """One claim of the ledger."""

    id: str
    paper: str
    location: str
    statement: str
    published: str
    reproduced: str
    scalar: str
    assurance: str
    """``exact`` (no number rounded), ``proven`` (ball enclosures), ``certified`` (two
    precisions agree) or ``floating`` (rounded arithmetic, unchecked)."""
    verdict: str
    """reproduced, reproduced-rounding, metric, typo, illustrated, undetermined, discrepancy
    or failed."""
    evidence: str
    finding: Optional[dict]
    """For a claim the paper gets wrong: what is printed, what is computed, the difference,
    the severity and why."""
    record: dict
    """The whole JSON record, with any field not named above."""

    @classmethod
    def from_record(cls, record: dict) -> "Claim":
        get = lambda key: record.get(key, "")
        return cls(get("id"), get("paper"), get("location"), get("statement"), get("published"),
                   get("reproduced"), get("scalar"), get("assurance"), get("verdict"), get("evidence"),
                   record.get("finding"), record)


class Ledger(dict):
    """``claims.json`` as a dict (``ledger["summary"]``, ``ledger["claims"]``), with the claims
    as :class:`Claim` objects: ``ledger.claim(id)``, ``ledger.by_verdict("discrepancy")``,
    iteration over claims and ``len``."""

    @property
    def summary(self) -> dict:
        """How many claims have each verdict and each assurance."""
        return self["summary"]

    @property
    def claims(self) -> List[Claim]:
        return [Claim.from_record(r) for r in self["claims"]]

    def claim(self, id: str) -> Claim:
        """The claim with this id (KeyError if there is none)."""
        for record in self["claims"]:
            if record.get("id") == id:
                return Claim.from_record(record)
        raise KeyError(id)

    def by_verdict(self, verdict: str) -> List[Claim]:
        return [c for c in self.claims if c.verdict == verdict]

    def verdicts(self) -> Dict[str, int]:
        """Verdict → number of claims, counted from the claims."""
        counts: Dict[str, int] = {}
        for c in self.claims:
            counts[c.verdict] = counts.get(c.verdict, 0) + 1
        return counts

    def __iter__(self) -> Iterator[Claim]:  # type: ignore[override]
        return iter(self.claims)

    def __len__(self) -> int:
        return len(self["claims"])

    def __repr__(self) -> str:
        return f"Ledger({len(self)} claims: {self.verdicts()})"
