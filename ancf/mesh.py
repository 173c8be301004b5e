"""The ANCF mesh of a fixed-ends scene: nodes, elements and their section properties.

Elements never straddle a segment joint or a point attachment (a node at each): each span
between them of length L gets ceil(L / h) equal elements, h the target element length.
Section values come from :func:`riser.model.sections.segment_properties` (inputs shared
by every method; the loads themselves are this package's).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from riser.model.scene import Scene
from riser.model.sections import segment_properties


@dataclass
class Mesh:
    """Nodes i = 0..n-1 (the anchor end first) and elements e = 0..n-2.

    s (n,) [m] the nodes' unstretched arc length; per element (ne,): l0 [m], EA [N], EI
    [N m2], mass [kg/m] (pipe and contents), weight [N/m] (submerged, + down), added
    [kg/m] (added mass normal to the axis), fluid [kg/m] (the displaced water, rho pi
    Dh^2 / 4), cdn, cdt [kg/m2] (drag: 0.5 rho Dh C_dn, 0.5 rho pi Dh C_dt), diameter [m]
    (outer). Per node (n,), the point attachments: point_weight [N, + down], point_mass
    [kg], point_added [kg] (isotropic), point_drag [kg/m] (0.5 rho C_D A). BA (ne,) [N s]
    the internal axial damping (the time domain's axial force gains BA d(eps)/dt; None is
    read as zeros).
    """

    s: np.ndarray
    l0: np.ndarray
    EA: np.ndarray
    EI: np.ndarray
    mass: np.ndarray
    weight: np.ndarray
    added: np.ndarray
    fluid: np.ndarray
    cdn: np.ndarray
    cdt: np.ndarray
    diameter: np.ndarray
    point_weight: np.ndarray = field(default=None)
    point_mass: np.ndarray = field(default=None)
    point_added: np.ndarray = field(default=None)
    point_drag: np.ndarray = field(default=None)
    BA: np.ndarray = field(default=None)

    def __post_init__(self) -> None:
        if self.BA is None:
            self.BA = np.zeros(len(self.l0))
        for name in ("point_weight", "point_mass", "point_added", "point_drag"):
            if getattr(self, name) is None:
                setattr(self, name, np.zeros(len(self.s)))

    @property
    def n(self) -> int:
        return len(self.s)

    @property
    def ne(self) -> int:
        return len(self.l0)

    @property
    def joints(self) -> np.ndarray:
        """(n,) bool: interior nodes where a section value changes or a point attachment
        sits (a field's derivative jumps there)."""
        out = np.zeros(self.n, bool)
        for v in (self.EA, self.EI, self.weight, self.mass, self.added, self.cdn):
            scale = np.maximum(np.maximum(np.abs(v[1:]), np.abs(v[:-1])), 1e-300)
            out[1:-1] |= np.abs(v[1:] - v[:-1]) > 1e-12 * scale
        pts = ((self.point_weight != 0) | (self.point_mass != 0) | (self.point_added != 0)
               | (self.point_drag != 0))
        out[1:-1] |= pts[1:-1]
        return out


#: the growth ratio of graded elements away from a point attachment
GRADING = 1.5


def point_loads(scene: Scene) -> dict:
    """s [m] -> the magnitude [N] of the point attachments' net weight there."""
    out: dict = {}
    g, rho = scene.gravity, scene.water_density
    for a in scene.attachments:
        out[a.s] = out.get(a.s, 0.0) + abs(a.net_weight(g, rho))
    return out


def _graded_start(EI: float, load: float | None, h: float) -> float:
    """The first element's length [m] next to a point load ``load`` [N]: the bending
    length sqrt(EI / load) of the kink it makes (the tension there is of the load's
    order), when shorter than ``h``; else ``h``. A C1 element cannot follow a kink shorter
    than itself: on a chain (EI 1e3 N m2) under a 87 kN clump, 2 m elements put the
    tension beside the clump 5.6 % off the BVP's, the tangent turning inside the element."""
    if not load:
        return h
    return min(h, max(math.sqrt(EI / load), 1e-3 * h))


def span_elements(length: float, h: float, h_a: float, h_b: float) -> list[float]:
    """Element lengths [m] across a span of ``length`` [m]: ``h`` at most, graded by
    :data:`GRADING` from ``h_a`` at its start and ``h_b`` at its end (equal lengths
    ceil(length / h) when neither is shorter than h)."""
    if h_a >= h and h_b >= h:
        k = max(1, int(math.ceil(length / h - 1e-9)))
        return [length / k] * k
    left, right = [], []
    x, y = h_a, h_b
    rest = length
    while x < h or y < h:
        if x < h and x < rest / 3.0:
            left.append(x)
            rest -= x
            x *= GRADING
        else:
            x = h
        if y < h and y < rest / 3.0:
            right.append(y)
            rest -= y
            y *= GRADING
        else:
            y = h
    k = max(1, int(math.ceil(rest / h - 1e-9)))
    return left + [rest / k] * k + right[::-1]


def build_mesh(scene: Scene, element_length: float, end_lengths=(None, None)) -> Mesh:
    """Mesh ``scene`` with elements of at most ``element_length`` [m], graded down to the
    bending length next to a point attachment (:func:`span_elements`) and to
    ``end_lengths`` [m] (anchor, hang-off; None: no grading) at the ends."""
    props = segment_properties(scene)
    cuts: list[float] = []
    for c in sorted(a.s for a in scene.attachments):
        if not cuts or c - cuts[-1] > 1e-6 * element_length:
            cuts.append(c)
    s = [0.0]
    cols: dict[str, list] = {k: [] for k in ("l0", "EA", "EI", "mass", "weight", "added",
                                             "fluid", "cdn", "cdt", "diameter", "BA")}
    loads = point_loads(scene)
    for p, seg in zip(props, scene.segments):
        D = scene.line_types[seg.line_type].outer_diameter
        edges = [p.s_start, *(c for c in cuts if p.s_start < c < p.s_end), p.s_end]
        for a, b in zip(edges[:-1], edges[1:]):
            h_a = _graded_start(p.EI, loads.get(a), element_length)
            h_b = _graded_start(p.EI, loads.get(b), element_length)
            if a == 0.0 and end_lengths[0] is not None:
                h_a = min(h_a, end_lengths[0])
            if b == props[-1].s_end and end_lengths[1] is not None:
                h_b = min(h_b, end_lengths[1])
            for length in span_elements(b - a, element_length, h_a, h_b):
                s.append(s[-1] + length)
                for name, value in (("l0", length), ("EA", p.EA), ("EI", p.EI),
                                    ("mass", p.mass), ("weight", p.weight),
                                    ("added", p.added_mass), ("fluid", p.fluid_mass),
                                    ("cdn", p.drag_normal_coef),
                                    ("cdt", p.drag_tangential_coef), ("diameter", D),
                                    ("BA", p.BA)):
                    cols[name].append(value)
    s_arr = np.asarray(s)
    s_arr[-1] = props[-1].s_end
    arrays = {k: np.asarray(v, float) for k, v in cols.items()}
    arrays["l0"] = np.diff(s_arr)
    points = {k: np.zeros(len(s_arr)) for k in ("point_weight", "point_mass", "point_added",
                                                "point_drag")}
    g, rho = scene.gravity, scene.water_density
    for a in scene.attachments:
        i = int(np.argmin(np.abs(s_arr - a.s)))
        points["point_weight"][i] += a.net_weight(g, rho)
        points["point_mass"][i] += a.mass
        points["point_added"][i] += a.added_mass(rho)
        points["point_drag"][i] += a.drag_coefficient(rho)
    return Mesh(s=s_arr, **arrays, **points)
