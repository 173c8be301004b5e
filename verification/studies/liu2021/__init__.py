"""Reproduction of Liu, Ai, Sun & Jia (2021), SCR with internal slug flow
(``riser-verify reproduce liu2021``): :mod:`.cases` (the runs and the report) and
:mod:`.analysis` (the paper's numbers, what is read off the time series)."""

from .cases import STUDY

__all__ = ["STUDY"]
