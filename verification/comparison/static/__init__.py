"""The static comparison: both methods on one scene, the agreement rows, the report and
further columns."""
