"""The memory a solve may take, estimated before solving (``[bvp] memory_budget``).

``solve_bvp`` holds, per mesh node, dense n x n blocks of the collocation Jacobian (the
right-hand side's Jacobian at the node and at the interval's middle, the two blocks of
the global matrix, their index arrays, the sparse copies and the LU factors) and a few
dozen arrays of n states (the state, f at nodes and middles, the spline, the residual
estimate). Its peak at m nodes for n states and k parameters is therefore

    peak ~ m (BYTES_PER_NODE_N2 n (n + k) + BYTES_PER_NODE_N n)        [bytes]

above what the process already holds. Measured (peak RSS of one solve_bvp pass at a
fixed mesh, scipy 1.17, this model): n = 6: 6.9 kB a node (20,000-100,000 nodes);
n = 12, k = 1: 19.7 kB a node (50,000 nodes); the former stacked form, n = 48: 284 kB a
node (3,000 nodes); n = 120: 2.8 MB a node (1,000 nodes). The coefficients below fit the
cases n = 6 and 12 from above (by 30-50 %: a refusal errs on the safe side) and the
stacked n = 48 case by 30 %. The peak is reached at the largest mesh, ``[bvp] max_nodes``
(solve_bvp stops before exceeding it).
"""

from __future__ import annotations

from .beam.layout import MIN_PIECE_NODES

#: bytes per node per state x (state + parameter) entry of the dense blocks
BYTES_PER_NODE_N2 = 150.0
#: bytes per node per state of the state-sized arrays
BYTES_PER_NODE_N = 600.0


def peak_bytes(n_state: int, n_param: int, nodes: int) -> float:
    """Estimated peak memory [bytes] of solve_bvp on ``nodes`` mesh nodes."""
    return nodes * (BYTES_PER_NODE_N2 * n_state * (n_state + n_param)
                    + BYTES_PER_NODE_N * n_state)


def over_budget(n_state: int, n_param: int, least_nodes: int, segments: int,
                max_nodes: int, budget_gb: float) -> str:
    """Why a solve of ``n_state`` states and ``n_param`` parameters on ``segments``
    pieces of line, whose coarsest starting mesh has ``least_nodes`` nodes, cannot run
    within [bvp] ``max_nodes`` and ``memory_budget`` [GB], else ''."""
    if least_nodes > max_nodes:
        return (f"the coarsest starting mesh of {segments:,} pieces of line (segments, runs "
                f"of identical ones merged) has {least_nodes:,} nodes ({MIN_PIECE_NODES} on "
                f"each and a pair at each joint), more than [bvp] max_nodes = "
                f"{max_nodes:,}; raise [bvp] max_nodes")
    need = peak_bytes(n_state, n_param, max_nodes) / 1e9
    if need <= budget_gb:
        return ""
    fits = int(budget_gb * 1e9 / peak_bytes(n_state, n_param, 1))
    return (f"a solve refined up to [bvp] max_nodes = {max_nodes:,} could take about "
            f"{need:.3g} GB (solve_bvp's collocation system: {n_state} states"
            f"{f' and {n_param} parameter' if n_param else ''}, "
            f"{peak_bytes(n_state, n_param, 1) / 1e3:.3g} kB a node), more than [bvp] "
            f"memory_budget = {budget_gb:g} GB; lower [bvp] max_nodes (at most {fits:,} "
            "nodes fit) or raise [bvp] memory_budget")
