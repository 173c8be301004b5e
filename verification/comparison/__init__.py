"""Comparing methods on the same scene: the protocol (:mod:`.protocol`: the agreement rows
and :func:`~.protocol.compare`), each row's tolerance and its reason (:mod:`.tolerances`),
the further columns beside the verdict (:mod:`.columns`; the analytic method's in
:mod:`.analytic_column`, a peer code's in its own folder of ``verification/peers/``), the
report of a comparison (:mod:`.report`) and the modal protocol (:mod:`.modes`: both methods'
natural modes of the same scene, frequency difference and MAC).

This folder never imports a peer, a study, a sweep or the command line
(``tests/test_layers.py``).
"""
