"""The line on one unit domain: pieces of piecewise-constant properties, their joints as
mesh points, and the blend that makes the right-hand side continuous for ``solve_bvp``.

The line (or, in the contact-zone form, the part of it beyond the lift-off point) is one
block of six states over the unit coordinate tau in [0, 1]. Piece k (a segment, or the
part of the first segment that is solved) occupies tau in [t_k, t_(k+1)] and maps to the
unstretched arc length s [m] by s = s_k + a_k (tau - t_k) with the stretch
a_k = ds/dtau = L_k / (t_(k+1) - t_k) [m]; the t_k are fixed when the problem is built
(proportional to the pieces' starting lengths), and a piece whose length is an unknown
parameter (the suspended length of the first segment) changes a_0 only.

Why a blend. ``solve_bvp`` evaluates the right-hand side f once per mesh node, and its
cubic collocation joins the intervals on either side of a node with that one slope: at a
joint, where the weight, EI, EA, drag and a_k jump, f has two values and the collocation
never converges there (it keeps inserting nodes). So each interior joint t_j carries a
pair of mesh nodes at t_j - g and t_j + g (the half-width ``gap`` g, 1e-7 of the domain:
about 0.1 mm on a 1,000 m line), which are never removed (solve_bvp only inserts nodes),
and between them every coefficient of f is blended linearly. The coefficients blended are
the products of the stretch and a property, C = (a, a w, a/EI, a/EA, a c_n, a c_t): every
term of f is one of them times a function of the state (bvp/beam/equations.py), so f is linear
in C and, with C linear in tau and symmetric about t_j, the integral of f over the gap
equals the sharp joint's up to the change of the state across the gap: the solution
outside the gap differs from the sharp-joint one by O(g^2), inside it by O(g) (proved in
tests/test_bvp_layout.py: g -> g/10 changes the solution by less than 1e-9 relative).
Inside the gap the solution is a near-quadratic, which the cubic collocation represents
exactly, so the gap never needs refining.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..mesh import clustered_mesh

#: half-width of the blend at an interior joint, in tau (the whole domain is 1)
GAP = 1.0e-7
#: the tau width of a point attachment's piece (of zero length: bvp/beam/points.py)
POINT_WIDTH = 1.0e-3
#: the fewest starting-mesh nodes on a piece (clustered at its ends)
MIN_PIECE_NODES = 8


@dataclass(frozen=True)
class Layout:
    """Pieces on the unit domain: ``edges`` (n + 1,) are the tau of their boundaries, 0 to
    1; ``gap`` is the blend half-width at each interior joint [-]."""

    edges: np.ndarray
    gap: float = GAP

    @classmethod
    def proportional(cls, lengths, gap: float | None = None) -> "Layout":
        """Pieces with tau widths proportional to ``lengths`` [m] (so ds/dtau is the same
        on every piece at these lengths); the gap (default ``GAP``) at most 5 % of the
        narrowest piece."""
        gap = GAP if gap is None else gap
        L = np.asarray(lengths, float)
        widths = L / float(np.sum(L))
        point = L == 0.0
        if np.any(point):
            # a point attachment (bvp/beam/points.py): a piece of zero length gets the width
            # POINT_WIDTH, the line's pieces share the rest in proportion to their lengths
            widths = np.where(point, POINT_WIDTH, widths * (1.0 - POINT_WIDTH * point.sum()))
        edges = np.concatenate([[0.0], np.cumsum(widths)])
        edges[-1] = 1.0
        return cls(edges, min(gap, 0.05 * float(np.min(np.diff(edges)))))

    @property
    def n(self) -> int:
        return len(self.edges) - 1

    @property
    def widths(self) -> np.ndarray:
        return np.diff(self.edges)

    def piece(self, tau: np.ndarray) -> np.ndarray:
        """Index of the piece holding each tau (a joint belongs to the piece after it)."""
        k = np.searchsorted(self.edges, tau, side="right") - 1
        return np.clip(k, 0, self.n - 1)

    def blend(self, tau: np.ndarray):
        """(kl, kr, lam): the coefficients at tau are (1 - lam) C[kl] + lam C[kr]; lam = 0
        (kl = kr = the piece) outside the gaps, rising linearly from 0 at t_j - gap to 1 at
        t_j + gap across an interior joint t_j."""
        tau = np.asarray(tau, float)
        k = self.piece(tau)
        kl, kr = k.copy(), k.copy()
        lam = np.zeros(tau.shape)
        if self.n == 1:
            return kl, kr, lam
        g = self.gap
        # a tau within rounding of a gap's end (the node pair t_j -/+ g, placed by
        # :meth:`mesh`) is outside it: a blend of 1e-9 there gave that node a piece's
        # coefficients off by 1e-9 of the jump, harmless at a joint between two lengths
        # of line, but next to a point attachment (a = 0 against a = L / width) a kink in
        # M' that no refinement beside the fixed node removes (bvp/beam/points.py)
        inner = g * (1.0 - 1e-6)
        left = (k > 0) & (tau - self.edges[k] < inner)            # just after joint k
        right = (k < self.n - 1) & (self.edges[np.minimum(k + 1, self.n)] - tau < inner)
        kl[left] = k[left] - 1
        lam[left] = (tau[left] - self.edges[k[left]] + g) / (2.0 * g)
        kr[right] = k[right] + 1
        lam[right] = (tau[right] - self.edges[k[right] + 1] + g) / (2.0 * g)
        return kl, kr, np.clip(lam, 0.0, 1.0)

    def s_of(self, tau: np.ndarray, lengths, s0: float = 0.0) -> np.ndarray:
        """Arc length s [m] at tau of the sharp map (pieces of ``lengths`` [m] from s0); the
        blended map differs from it only inside a gap, by at most g |a_(k+1) - a_k| / 4."""
        tau = np.asarray(tau, float)
        L = np.asarray(lengths, float)
        k = self.piece(tau)
        starts = s0 + np.concatenate([[0.0], np.cumsum(L)])
        return starts[k] + L[k] / self.widths[k] * (tau - self.edges[k])

    def tau_of(self, s: np.ndarray, lengths, s0: float = 0.0) -> np.ndarray:
        """The inverse of :meth:`s_of` (s [m] clipped to the pieces)."""
        s = np.asarray(s, float)
        L = np.asarray(lengths, float)
        starts = s0 + np.concatenate([[0.0], np.cumsum(L)])
        k = np.clip(np.searchsorted(starts, s, side="right") - 1, 0, self.n - 1)
        frac = np.clip((s - starts[k]) / np.where(L[k] > 0.0, L[k], 1.0), 0.0, 1.0)
        return self.edges[k] + frac * self.widths[k]

    def in_gap(self, tau: np.ndarray) -> np.ndarray:
        """True for tau within 1.5 gaps of an interior joint (the node pairs)."""
        tau = np.asarray(tau, float)
        if self.n == 1:
            return np.zeros(tau.shape, bool)
        j = self.edges[1:-1]
        i = np.clip(np.searchsorted(j, tau), 1, j.size)
        near = np.minimum(np.abs(tau - j[i - 1]), np.abs(tau - j[np.minimum(i, j.size - 1)]))
        return near < 1.5 * self.gap

    def counts(self, total: int) -> np.ndarray:
        """Starting-mesh nodes per piece: ``total`` shared in proportion to the tau widths,
        at least MIN_PIECE_NODES on each."""
        return np.maximum(MIN_PIECE_NODES, np.rint(total * self.widths).astype(int))

    def mesh(self, total: int) -> np.ndarray:
        """The starting mesh: on each piece a mesh clustered at its ends
        (bvp.mesh.clustered_mesh: the bending boundary layers sit at the joints), and at
        each interior joint the node pair t_j -/+ gap."""
        parts = []
        for k, m in enumerate(self.counts(total)):
            a = self.edges[k] + (self.gap if k > 0 else 0.0)
            b = self.edges[k + 1] - (self.gap if k < self.n - 1 else 0.0)
            parts.append(a + (b - a) * clustered_mesh(int(m)))
        tau = np.concatenate(parts)
        tau[0], tau[-1] = 0.0, 1.0
        return tau
