"""The scenes of the end-condition study, built through the scene file's tables
(:func:`riser.io.scene_file.scene_from_dict`), as a user's file gives them: the
closed-form scenes of issue 35 (the same lines as the tests of the end conditions and the
attachments).

- :func:`vertical`: a weightless vertical line of L = 100 m, EI = 1e7 N m2, pulled by a
  top tensioner of T = 1e5 N (lambda L = L sqrt(T/EI) = 10), optionally in a current and
  with end joints;
- :func:`hanging_chain`: 100 m of line of 200 N/m hanging from (0, 170) m with a free lower
  end (EI = 1 N m2, no added mass);
- :func:`cable`: 150 m of cable of 200 N/m between pinned ends 110 m apart and 50 m
  apart in height, one attachment at s = 90 m.
"""

from __future__ import annotations

import copy

from riser.io.scene_file import scene_from_dict

#: the vertical line: length [m], the tensioner's pull [N], EI [N m2], EA [N]
L, T, EI, EA = 100.0, 1.0e5, 1.0e7, 1.0e9
#: the uniform current on the tensioned line [m/s] and its normal drag coefficient
CURRENT = 0.3
#: the hanging chain's top [m] and submerged weight [N/m]
CHAIN_TOP, CHAIN_WEIGHT = 170.0, 200.0
#: the cable: length, span, rise [m], weight [N/m], EA [N], the attachment's arc length [m]
CABLE_LENGTH, CABLE_SPAN, CABLE_RISE = 150.0, 110.0, 50.0
CABLE_WEIGHT, CABLE_EA, S_P = 200.0, 1.0e8, 90.0
#: the two attachments: a clump weight (net +17.1 kN) and a buoy (net -10.2 kN)
ATTACHMENTS = {"clump": {"mass": 2000.0, "volume": 0.25},
               "buoy": {"mass": 500.0, "volume": 1.5}}


def pipe(**keys) -> dict:
    """A line type: a 0.3 m pipe with a 0.25 m bore, 100 kg/m, EA 1e9 N, EI 1e7 N m2."""
    table = {"outer_diameter": 0.3, "inner_diameter": 0.25, "mass_per_length": 100.0,
             "axial_stiffness": EA, "bending_stiffness": EI}
    table.update(keys)
    return table


def line(length, anchor, hang_off, *, line_type: dict, submerged_weight: float,
         name: str, environment: dict) -> dict:
    """A scene's tables: one segment between fixed ends."""
    return {"name": name, "line_types": {"p": copy.deepcopy(line_type)},
            "segments": [{"line_type": "p", "length": length,
                          "submerged_weight": submerged_weight}],
            "ends": {"anchor": list(anchor), "hang_off": list(hang_off)},
            "environment": copy.deepcopy(environment)}


def vertical(*, current: float = 0.0, anchor_joint=None, hang_off_joint=None,
             name: str = "ttr") -> dict:
    """The weightless vertical line from (0, 0) to (0, L) pulled by the tensioner (no
    seabed: the anchor holds it); ``current`` [m/s] uniform along +x."""
    env = {"water_depth": 200.0, "gravity": 9.81, "water_density": 1025.0}
    if current:
        env["current"] = {"heights": [0.0, 200.0], "speeds": [current, current]}
    data = line(L, (0.0, 0.0), (0.0, L), submerged_weight=0.0, name=name, environment=env,
                line_type=pipe(drag_normal=1.0, drag_tangential=0.0))
    data["ends"]["tensioner"] = {"top_tension": T}
    if anchor_joint:
        data["ends"]["anchor_joint"] = dict(anchor_joint)
    if hang_off_joint:
        data["ends"]["hang_off_joint"] = dict(hang_off_joint)
    return data


def hanging_chain() -> dict:
    """The chain hanging from (0, CHAIN_TOP) with its lower end free."""
    data = line(L, (0.0, CHAIN_TOP - 110.0), (0.0, CHAIN_TOP), submerged_weight=CHAIN_WEIGHT,
                name="hanging-chain", line_type=pipe(bending_stiffness=1.0, added_mass=0.0),
                environment={"water_depth": 200.0, "gravity": 9.81,
                             "water_density": 1025.0})
    data["ends"]["anchor_joint"] = {"kind": "free"}
    return data


def cable(kind: str) -> dict:
    """The cable with the attachment ``kind`` (a key of :data:`ATTACHMENTS`) at S_P."""
    data = line(CABLE_LENGTH, (0.0, 10.0), (CABLE_SPAN, 10.0 + CABLE_RISE),
                submerged_weight=CABLE_WEIGHT, name=f"cable-{kind}",
                line_type=pipe(bending_stiffness=1.0, axial_stiffness=CABLE_EA),
                environment={"water_depth": 200.0, "gravity": 9.81, "water_density": 1025.0})
    data["attachments"] = [{"s": S_P, **ATTACHMENTS[kind]}]
    return data


def scene(data: dict):
    """The Scene of a scene's tables (validated as a file is)."""
    return scene_from_dict(data, f"{data['name']} (reproduce ends)")
