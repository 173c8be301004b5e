"""The ANCF statics: Newton from its own starting shape (newton.py, start.py)."""
