"""``riser-verify bench``: what the methods cost, measured side by side in one run
(:mod:`.methods`: the VFIFE kernel and solver, the ANCF's statics and dynamics beside it
(:mod:`.ancf`), the BVP, the analytic method against the BVP;
``reports/bench/bench.json``). The sweep's throughput is measured by
:mod:`verification.sweeps.bench`, a peer's cost by its own folder of
``verification/peers/``."""
