"""Comparing methods on the same scene: the protocol (:mod:`.static.protocol`: the agreement rows
and :func:`~.static.protocol.compare`), each row's tolerance and its reason (:mod:`.tolerances`),
the further columns beside the verdict (:mod:`.static.columns`; the analytic method's in
:mod:`.static.analytic_column`, a peer code's in its own folder of ``verification/peers/``), the
report of a comparison (:mod:`.static.report`) and the modal protocol (:mod:`.modes`: both methods'
natural modes of the same scene, frequency difference and MAC).

This folder never imports a peer, a study, a sweep or the command line
(``tests/test_layers.py``).
"""
