#!/usr/bin/env python3
"""Equivalent lateral force design of the example BRB frames and writer of their model files.

Run from anywhere: `python3 frames/design.py`. Python 3 standard library only.
It prints the design tables, rewrites the generated part of frames/README.md and writes

    frames/brbf3/model.json       3-storey planar BRBF (one chevron-braced bay + leaning column)
    frames/brbf3/braces/*.json    one brace file per storey
    frames/brbf9/...              9-storey planar BRBF, the same layout
    frames/brbf4_3d/...           4-storey 3D building, perimeter BRBFs in X and Y, rigid floors

Codes (what each formula is): ASCE/SEI 7-16 (site coefficients Tables 11.4-1/11.4-2, 11.4.8
exception 2, Table 12.2-1 line B.26, Eqs 12.8-1 to 12.8-7, 12.8-11 to 12.8-13, Table 12.8-1
and 12.8-2, accidental torsion 12.8.4.2), ANSI/AISC 341-16 F4 (adjusted brace strengths,
capacity design of beams and columns), ANSI/AISC 360-16 E3 (column buckling) and F2 (beam
plastic moment). Units: N, mm, s, MPa, tonne; kN and m only in the printed tables.
"""

import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
G = 9806.65  # mm/s^2, standard gravity
KPA = 1e-3  # N/mm^2 per kPa

# ---------------------------------------------------------------------------------------------
# Site and system (ASCE 7-16)
# ---------------------------------------------------------------------------------------------
SITE = {
    "location": "high-seismicity Los Angeles site",
    "site_class": "D",
    "SS": 1.5,
    "S1": 0.6,
    "TL": 8.0,  # s, long-period transition period of coastal Los Angeles (ASCE 7-16 Fig. 22-14)
    "risk_category": "II",
    "Ie": 1.0,  # Table 1.5-2
}
SYSTEM = {
    "name": "buckling-restrained braced frame, non-moment-resisting beam-column connections "
            "(ASCE 7-16 Table 12.2-1, B.26)",
    "R": 8.0,
    "Omega0": 2.5,
    "Cd": 5.0,
    "Ct": 0.0731,  # Table 12.8-2, BRBF, h in m (0.03 with h in ft)
    "x": 0.75,
    "rho": 1.0,  # 12.3.4.2 (b): at least two braced bays per perimeter line in each direction
}
ALLOWABLE_DRIFT = 0.020  # Table 12.12-1, risk category II, "all other structures"


def site_coefficient_fa(site_class, ss):
    """ASCE 7-16 Table 11.4-1, site class D (linear interpolation between the columns)."""
    assert site_class == "D"
    table = [(0.25, 1.6), (0.5, 1.4), (0.75, 1.2), (1.0, 1.1), (1.25, 1.0), (1.5, 1.0)]
    return interpolate(table, ss)


def site_coefficient_fv(site_class, s1):
    """ASCE 7-16 Table 11.4-2, site class D (values of the table; footnote: 11.4.8 applies)."""
    assert site_class == "D"
    table = [(0.1, 2.4), (0.2, 2.2), (0.3, 2.0), (0.4, 1.9), (0.5, 1.8), (0.6, 1.7)]
    return interpolate(table, s1)


def interpolate(table, x):
    if x <= table[0][0]:
        return table[0][1]
    for (x0, y0), (x1, y1) in zip(table, table[1:]):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return table[-1][1]


def spectrum():
    fa = site_coefficient_fa(SITE["site_class"], SITE["SS"])
    fv = site_coefficient_fv(SITE["site_class"], SITE["S1"])
    sms = fa * SITE["SS"]  # Eq 11.4-1
    sm1 = fv * SITE["S1"]  # Eq 11.4-2
    sds = 2.0 / 3.0 * sms  # Eq 11.4-3
    sd1 = 2.0 / 3.0 * sm1  # Eq 11.4-4
    return {"Fa": fa, "Fv": fv, "SMS": sms, "SM1": sm1, "SDS": sds, "SD1": sd1,
            "Ts": sd1 / sds, "T0": 0.2 * sd1 / sds}


def upper_limit_coefficient(sd1):
    """ASCE 7-16 Table 12.8-1."""
    return interpolate([(0.1, 1.7), (0.15, 1.6), (0.2, 1.5), (0.3, 1.4), (0.4, 1.4)], sd1)


def seismic_response_coefficient(sp, period, R, Ie):
    """Cs (Eqs 12.8-2 to 12.8-6) with ASCE 7-16 11.4.8 exception 2, which lets site class D
    with S1 >= 0.2 skip the site-specific hazard analysis when Cs is taken as Eq 12.8-2 for
    T <= 1.5 Ts and as 1.5 times Eq 12.8-3 for 1.5 Ts < T <= TL. Returns (Cs, which rule)."""
    sds, sd1, ts, tl = sp["SDS"], sp["SD1"], sp["Ts"], SITE["TL"]
    cs_short = sds / (R / Ie)  # Eq 12.8-2
    if period <= 1.5 * ts:
        cs, rule = cs_short, "Eq 12.8-2 (T <= 1.5 Ts, 11.4.8 exc. 2)"
    elif period <= tl:
        cs, rule = 1.5 * sd1 / (period * R / Ie), "1.5 x Eq 12.8-3 (1.5 Ts < T <= TL, 11.4.8 exc. 2)"
    else:
        cs, rule = sd1 * tl / (period ** 2 * R / Ie), "Eq 12.8-4"
    cs = min(cs, cs_short)
    cs_min = max(0.044 * sds * Ie, 0.01)  # Eq 12.8-5
    if SITE["S1"] >= 0.6:
        cs_min = max(cs_min, 0.5 * SITE["S1"] / (R / Ie))  # Eq 12.8-6
    if cs < cs_min:
        cs, rule = cs_min, "lower limit Eq 12.8-5/12.8-6"
    return cs, rule


def distribution_exponent(period):
    """k of Eq 12.8-12: 1 for T <= 0.5 s, 2 for T >= 2.5 s, linear in between."""
    return min(2.0, max(1.0, 1.0 + (period - 0.5) / 2.0))


# ---------------------------------------------------------------------------------------------
# Steel shapes: AISC Steel Construction Manual (15th ed.) W-shape properties in inches,
# converted to mm here. (A in^2, Ix in^4 strong axis, Iy in^4 weak axis, J in^4, Zx in^3)
# ---------------------------------------------------------------------------------------------
INCH = 25.4
W_SHAPES = {
    # columns
    "W14X48": (14.1, 484, 51.4, 1.45, 78.4),
    "W14X68": (20.0, 722, 121, 3.01, 115),
    "W14X90": (26.5, 999, 362, 4.06, 157),
    "W14X109": (32.0, 1240, 447, 7.12, 192),
    "W14X132": (38.8, 1530, 548, 12.3, 234),
    "W14X159": (46.7, 1900, 748, 19.7, 287),
    "W14X193": (56.8, 2400, 931, 34.8, 355),
    "W14X233": (68.5, 3010, 1150, 59.5, 436),
    "W14X283": (83.3, 3840, 1440, 104, 542),
    "W14X342": (101, 4900, 1810, 178, 672),
    "W14X398": (117, 6000, 2170, 273, 801),
    # beams
    "W18X35": (10.3, 510, 15.3, 0.506, 66.5),
    "W18X50": (14.7, 800, 40.1, 1.24, 101),
    "W21X62": (18.3, 1330, 57.5, 1.83, 144),
    "W24X76": (22.4, 2100, 82.5, 2.68, 200),
    "W24X84": (24.7, 2370, 94.4, 3.70, 224),
    "W27X94": (27.6, 3270, 124, 4.03, 278),
    "W30X108": (31.7, 4470, 146, 4.99, 346),
    "W33X130": (38.3, 6710, 218, 7.37, 467),
    "W36X150": (44.3, 9040, 270, 10.1, 581),
}
COLUMN_SHAPES = [n for n in W_SHAPES if n.startswith("W14")]
BEAM_SHAPES = [n for n in W_SHAPES if not n.startswith("W14")]
E_STEEL = 200000.0  # MPa
G_STEEL = 77200.0  # MPa
FY_FRAME = 345.0  # MPa, A992 columns and beams
BEAM_COLUMN_TRIBUTARY_WIDTH = 4500.0  # mm of floor each frame beam and column carries across


def shape_mm(name):
    a, ix, iy, j, zx = W_SHAPES[name]
    return {"A": a * INCH ** 2, "Ix": ix * INCH ** 4, "Iy": iy * INCH ** 4,
            "J": j * INCH ** 4, "Zx": zx * INCH ** 3}


def section_entry(name):
    """The model file's elastic section: bending in the frame plane about the element's local
    y (strong axis Ix -> "Iy"), out of plane about local z (weak axis -> "Iz")."""
    s = {k: float("%.6g" % v) for k, v in shape_mm(name).items()}
    return {"E": E_STEEL, "G": G_STEEL, "A": s["A"], "Iy": s["Ix"], "Iz": s["Iy"], "J": s["J"]}


def column_strength(name, length):
    """phi_c Pn of AISC 360-16 E3, K = 1 about the weak axis over the storey height."""
    s = shape_mm(name)
    slenderness = length / math.sqrt(s["Iy"] / s["A"])
    fe = math.pi ** 2 * E_STEEL / slenderness ** 2
    if slenderness <= 4.71 * math.sqrt(E_STEEL / FY_FRAME):
        fcr = 0.658 ** (FY_FRAME / fe) * FY_FRAME
    else:
        fcr = 0.877 * fe
    return 0.9 * fcr * s["A"]


def beam_strength(name):
    """phi_b Mp of AISC 360-16 F2 (laterally braced beam)."""
    return 0.9 * FY_FRAME * shape_mm(name)["Zx"]


def lightest(names, ok):
    """The lightest shape (by area) of `names` for which ok(name) holds."""
    for name in sorted(names, key=lambda n: W_SHAPES[n][0]):
        if ok(name):
            return name
    raise SystemExit("design.py: no shape is strong enough; extend the shape table")


# ---------------------------------------------------------------------------------------------
# BRB core, end zones and casing
# ---------------------------------------------------------------------------------------------
FYSC = 262.0  # MPa, A36 core (38 ksi), specified; Ry = 1.1 NOT applied in the model
PHI_BRB = 0.9
BETA = 1.15  # compression adjustment assumed (AISC 341 qualification tests: 1.05 to 1.2)
YIELDING_FRACTION = 0.65  # yielding length / work-point length
TRANSITION_LENGTH = 150.0  # mm, each end
# The transition is inserted into the casing over its whole length (the casing overlaps it),
# so that the core cannot hinge where it leaves the casing: without the overlap the chain of a
# casing between two long end zones has a hinge mechanism there (validation/aisc/README.md,
# "brbf3"; real BRBs insert the stiffened end into the restrainer, Takeuchi & Wada 2018).
CASING_OVERLAP = TRANSITION_LENGTH
# Brace ends: gusset connections welded or bolted to the beam-column joints. In a frame model a
# `brb` element shares all six DOF of its work-point nodes (README "Frame model files"); the
# brace file says "fixed" so that a stand-alone test of it (`brb cyclic`, `brb check`) has the
# same end conditions.
BRACE_ENDS = "fixed"
PLATE_THICKNESSES = [12.0, 16.0, 20.0, 25.0, 30.0, 40.0, 50.0]  # mm
GAP = 1.0  # mm per side, both directions
FRICTION = 0.1  # BRB_SOURCE_FACTS section 4
MORTAR_COVER = 20.0  # mm, least mortar between the core plate's edge (+gap) and the tube
CASING_SAFETY = 1.5  # Euler load of the casing over the brace's largest compression
# Core steel: E, nu of structural steel, fy = Fysc, the hardening of
# examples/material/steel_s275_chaboche_voce.json (two Chaboche back-stresses and Voce);
# no damage (no Gf): core fracture is off.
CORE_STEEL = {"E": E_STEEL, "nu": 0.3, "fy": FYSC, "H_kin": 0, "H_iso": 0,
              "chaboche": [{"C": 6000, "gamma": 60}, {"C": 1500, "gamma": 8}],
              "voce": {"Q": 40, "b": 10}}
TUBE_STEEL = {"E": E_STEEL, "nu": 0.3, "fy": 317, "H_kin": 2000, "H_iso": 0}  # A500 Gr. B
# Mortar of examples/braces/girona_D3_restrained.json (Girona tests; Gf assumed there).
MORTAR = {"E": 17520, "nu": 0.2, "fc": 50, "ft": 5, "Gf": 0.1}
HSS_OUTER = [150.0, 160.0, 180.0, 200.0, 220.0, 250.0, 260.0, 300.0, 350.0, 400.0, 450.0, 500.0]
HSS_WALL = [6.0, 8.0, 10.0, 12.5, 16.0, 20.0]


def ceil_to(value, step):
    return step * math.ceil(value / step - 1e-9)


def core_plate(area_required):
    """The thinnest standard plate whose width, rounded up to 5 mm, is at most 10 thicknesses."""
    for t in PLATE_THICKNESSES:
        width = ceil_to(area_required / t, 5.0)
        if width <= 10.0 * t:
            return width, t
    raise SystemExit("design.py: core area too large for the plate table")


def steel_stress_at(strain):
    """Monotonic stress of CORE_STEEL at a core strain (closed form of the Chaboche terms),
    with the Voce isotropic term fully saturated (many cycles): the strain-hardened strength
    used for omega."""
    plastic = max(0.0, strain - CORE_STEEL["fy"] / CORE_STEEL["E"])
    back = sum(t["C"] / t["gamma"] * (1.0 - math.exp(-t["gamma"] * plastic))
               for t in CORE_STEEL["chaboche"])
    return CORE_STEEL["fy"] + back + CORE_STEEL["voce"]["Q"]


def cruciform_depth(area, width, thickness):
    """Depth of a cruciform (plates width x t and depth x t) of at least `area`, 5 mm steps."""
    return ceil_to(area / thickness - width + thickness, 5.0)


def casing_tube(core_width, core_thickness, euler_required, length):
    """The lightest square HSS (mm) that leaves MORTAR_COVER around what it holds (the core,
    and the transition where the casing overlaps it: pass the largest extent) + gaps, has a
    width-to-wall ratio <= 35 and an Euler load (tube steel only, mortar neglected: cracked,
    pinned over the whole work-point length) >= euler_required."""
    best = None
    for b in HSS_OUTER:
        for w in HSS_WALL:
            inner = b - 2.0 * w
            if inner < max(core_width, core_thickness) + 2.0 * GAP + 2.0 * MORTAR_COVER:
                continue
            if b / w > 35.0:
                continue
            inertia = (b ** 4 - inner ** 4) / 12.0
            euler = math.pi ** 2 * E_STEEL * inertia / length ** 2
            if euler < euler_required:
                continue
            area = b * b - inner * inner
            if best is None or area < best["area"]:
                best = {"outer": b, "wall": w, "area": area, "inertia": inertia, "euler": euler}
    if best is None:
        raise SystemExit("design.py: no tube in the HSS table fits")
    return best


def design_brace(name, force_required, length, height, cos_theta):
    """One brace: core area, plate, omega and beta x omega x Py, end zones, casing, lengths."""
    area_required = force_required / (PHI_BRB * FYSC)
    width, thickness = core_plate(area_required)
    area = width * thickness
    py = FYSC * area
    yielding = math.floor(YIELDING_FRACTION * length / 10.0) * 10.0
    # Core strain at 2 x the allowable storey drift (the K3 qualification range): the storey
    # displacement projected on the brace axis (AISC341_NOTES "Kinematics"), all of it in
    # the yielding zone (end zones rigid: conservative).
    strain = 2.0 * ALLOWABLE_DRIFT * height * cos_theta / yielding
    omega = steel_stress_at(strain) / FYSC
    pmax = BETA * omega * py
    # End zones stay elastic at Pmax: transition area >= 1.1 Pmax / Fy, connection 1.5 Pmax / Fy.
    trans_width = ceil_to(1.25 * width, 5.0)
    trans_depth = cruciform_depth(1.1 * pmax / FYSC, trans_width, thickness)
    conn_width = ceil_to(1.5 * width, 5.0)
    conn_depth = cruciform_depth(1.5 * pmax / FYSC, conn_width, thickness)
    connection = (length - yielding - 2.0 * TRANSITION_LENGTH) / 2.0
    held_width = max(width, trans_width, trans_depth) if CASING_OVERLAP > 0.0 else width
    tube = casing_tube(held_width, thickness, CASING_SAFETY * pmax, length)
    brace_file = {
        "name": name,
        "units": "mm",
        "core": {
            "section": {"shape": "rectangle", "width": width, "depth": thickness},
            "steel": CORE_STEEL,
            "yielding_length": yielding,
            "elements": 16,
        },
        "transition": {"length": TRANSITION_LENGTH,
                       "section": {"shape": "cruciform", "width": trans_width,
                                   "depth": trans_depth, "thickness": thickness}},
        "connection": {"length": connection,
                       "section": {"shape": "cruciform", "width": conn_width,
                                   "depth": conn_depth, "thickness": thickness}},
        "ends": BRACE_ENDS,
        "casing": {
            "tube": {"shape": "rectangular_tube", "width": tube["outer"],
                     "depth": tube["outer"], "wall": tube["wall"]},
            "tube_steel": TUBE_STEEL,
            "mortar": MORTAR,
            "gap": GAP,
            "friction": FRICTION,
            "overlap": CASING_OVERLAP,
        },
    }
    return {
        "name": name, "Pu": force_required, "Asc_required": area_required,
        "core_width": width, "core_thickness": thickness, "Asc": area, "Py": py,
        "work_point_length": length, "yielding_length": yielding,
        "transition_length": TRANSITION_LENGTH, "connection_length": connection,
        "core_strain_2x_drift": strain, "omega": omega, "beta": BETA, "Pmax": pmax,
        "transition_area": thickness * (trans_width + trans_depth - thickness),
        "connection_area": thickness * (conn_width + conn_depth - thickness),
        "tube": "%gx%gx%g" % (tube["outer"], tube["outer"], tube["wall"]),
        "casing_euler": tube["euler"], "file": brace_file,
    }


# ---------------------------------------------------------------------------------------------
# Building-level ELF design
# ---------------------------------------------------------------------------------------------
def elf(building):
    """Seismic weight, period, Cs, V and its vertical distribution for the whole building."""
    sp = spectrum()
    heights = building["storey_heights"]
    levels = [sum(heights[: i + 1]) for i in range(len(heights))]  # mm above the base
    hn = levels[-1]
    plan = building["plan"][0] * building["plan"][1]  # mm^2
    weights = [building["floor_load"] * KPA * plan] * (len(heights) - 1)
    weights.append(building["roof_load"] * KPA * plan)
    ta = SYSTEM["Ct"] * (hn / 1000.0) ** SYSTEM["x"]  # Eq 12.8-7, h in m
    cu = upper_limit_coefficient(sp["SD1"])
    period = ta  # designed with Ta (12.8.2: always allowed); CuTa caps a computed period
    cs, cs_rule = seismic_response_coefficient(sp, period, SYSTEM["R"], SITE["Ie"])
    w_total = sum(weights)
    v = cs * w_total  # Eq 12.8-1
    k = distribution_exponent(period)
    wh = [w * h ** k for w, h in zip(weights, levels)]
    cvx = [x / sum(wh) for x in wh]  # Eq 12.8-12
    forces = [c * v for c in cvx]  # Eq 12.8-11
    shears = [sum(forces[i:]) for i in range(len(forces))]  # Eq 12.8-13
    return {"spectrum": sp, "levels": levels, "hn": hn, "weights": weights, "W": w_total,
            "Ta": ta, "Cu": cu, "CuTa": cu * ta, "T": period, "Cs": cs, "Cs_rule": cs_rule,
            "V": v, "k": k, "Cvx": cvx, "forces": forces, "shears": shears}


def frame_members(building, share, shears, storey_braces):
    """Braces, chevron beams and columns of one braced bay carrying `share` of the storey
    shears. Two braces per storey (inverted-V chevron), each Pu = V_x / (2 cos theta)."""
    bay = building["bay"]
    heights = building["storey_heights"]
    sp = spectrum()
    gravity_factor = 1.2 + 0.2 * sp["SDS"]  # (1.2 + 0.2 SDS) D, ASCE 7-16 12.4.2.3 comb. 6
    q = [building["floor_load"] * KPA] * (len(heights) - 1) + [building["roof_load"] * KPA]
    braces = []
    for i, h in enumerate(heights):
        length = math.hypot(bay / 2.0, h)
        cos_theta = bay / 2.0 / length
        pu = SYSTEM["rho"] * share * shears[i] / (2.0 * cos_theta)
        braces.append(design_brace(storey_braces(i), pu, length, h, cos_theta))
    # Chevron beam (AISC 341-16 F4.4a): unbalanced vertical force of compression
    # beta omega Py and tension omega Py at midspan, braces giving no support to gravity;
    # simply supported over the bay (conservative); gravity of BEAM_COLUMN_TRIBUTARY_WIDTH.
    beams = []
    for i, b in enumerate(braces):
        sin_theta = heights[i] / b["work_point_length"]
        unbalanced = (BETA - 1.0) * b["omega"] * b["Py"] * sin_theta
        w_line = gravity_factor * q[i] * BEAM_COLUMN_TRIBUTARY_WIDTH
        mu = unbalanced * bay / 4.0 + w_line * bay ** 2 / 8.0
        beams.append({"Mu": mu, "shape": lightest(BEAM_SHAPES, lambda n: beam_strength(n) >= mu)})
    # Columns (AISC 341-16 F4.3): the vertical components of every compression brace above
    # at beta omega Py (all on one side: conservative), half the unbalanced beam force of
    # each floor above, and the tributary gravity (bay/2 x tributary width per floor).
    columns = []
    n = len(heights)
    for j in range(n):
        pu = 0.0
        for i in range(j, n):
            b = braces[i]
            sin_theta = heights[i] / b["work_point_length"]
            if i > j:
                pu += BETA * b["omega"] * b["Py"] * sin_theta
            pu += 0.5 * (BETA - 1.0) * b["omega"] * b["Py"] * sin_theta
            pu += gravity_factor * q[i] * bay / 2.0 * BEAM_COLUMN_TRIBUTARY_WIDTH
        columns.append({"Pu": pu})
    # Column splices every two storeys: one shape per pair, for the larger demand.
    for j in range(0, n, 2):
        group = range(j, min(n, j + 2))
        need = max(columns[g]["Pu"] for g in group)
        h = max(heights[g] for g in group)
        shape = lightest(COLUMN_SHAPES, lambda s: column_strength(s, h) >= need)
        for g in group:
            columns[g]["shape"] = shape
            columns[g]["phiPn"] = column_strength(shape, heights[g])
    return braces, beams, columns


# ---------------------------------------------------------------------------------------------
# Model files
# ---------------------------------------------------------------------------------------------
DAMPING = {"type": "rayleigh", "modes": [1, 3], "ratios": [0.02, 0.02],
           "stiffness": "initial", "exclude_braces": True}
ANALYSIS = {"integrator": "newmark", "dt": 0.005, "free_vibration": 0.0, "drift_limit": 0.10}
RECORDERS = {"drifts": True, "floor_accelerations": True, "base_shear": True, "energy": True,
             "braces": "all"}
# Leaning column: axially stiff (the gravity columns' area), bending stiffness negligible.
LEANING_SECTION = {"E": E_STEEL, "G": G_STEEL, "A": 1.0e5, "Iy": 1.0e4, "Iz": 1.0e4,
                   "J": 1.0e4}


def design_block(b, share, braces, beams, columns, extra=None):
    sp = b["elf"]["spectrum"]
    e = b["elf"]
    block = {
        "source": "frames/design.py (ASCE 7-16 ELF; see frames/README.md)",
        "site": dict(SITE), "system": SYSTEM["name"],
        "R": SYSTEM["R"], "Omega0": SYSTEM["Omega0"], "Cd": SYSTEM["Cd"], "Ie": SITE["Ie"],
        "rho": SYSTEM["rho"],
        "Fa": sp["Fa"], "Fv": sp["Fv"], "SMS": sp["SMS"], "SM1": sp["SM1"],
        "SDS": sp["SDS"], "SD1": sp["SD1"], "Ts": sp["Ts"], "TL": SITE["TL"],
        "hn": e["hn"], "Ct": SYSTEM["Ct"], "x": SYSTEM["x"], "Ta": e["Ta"], "Cu": e["Cu"],
        "CuTa": e["CuTa"], "T": e["T"], "Cs": e["Cs"], "Cs_rule": e["Cs_rule"], "k": e["k"],
        "building_seismic_weight": e["W"], "building_V": e["V"],
        "frame_share": share,
        "seismic_weight": share * e["W"],
        "floor_weights": [share * w for w in e["weights"]],
        "V": share * e["V"],
        "Cvx": e["Cvx"],
        "floor_forces": [share * f for f in e["forces"]],
        "story_shears": [share * v for v in e["shears"]],
        "braces": [{k: v for k, v in br.items() if k != "file"} for br in braces],
        "beams": beams, "columns": columns,
        "units": {"force": "N", "length": "mm", "mass": "tonne", "period": "s"},
    }
    if extra:
        block.update(extra)
    return block


def planar_model(b):
    """Planar chevron BRBF in the X-Z plane: columns at X = 0 and bay, beam split at midspan,
    leaning column at X = bay + 4500 tied to the right column line by equal_dof ux."""
    share = 1.0 / b["braced_bays_per_direction"]
    braces, beams, columns = frame_members(
        b, share, b["elf"]["shears"], lambda i: "%s_story%d" % (b["name"], i + 1))
    bay = b["bay"]
    lean_x = bay + 4500.0
    levels = [0.0] + b["elf"]["levels"]
    n = len(b["storey_heights"])
    nodes, supports, constraints, masses, elements, loads = [], [], [], [], [], []
    sections = {"LEANING": LEANING_SECTION}
    for f in range(n + 1):
        z = levels[f]
        nodes.append({"id": 100 * f + 1, "xyz": [0.0, 0.0, z]})
        if f > 0:
            nodes.append({"id": 100 * f + 2, "xyz": [bay / 2.0, 0.0, z]})
        nodes.append({"id": 100 * f + 3, "xyz": [bay, 0.0, z]})
        nodes.append({"id": 100 * f + 9, "xyz": [lean_x, 0.0, z]})
    supports = [{"node": 1, "fix": "fixed"}, {"node": 3, "fix": "fixed"},
                {"node": 9, "fix": "pinned"}]
    q = [b["floor_load"] * KPA] * (n - 1) + [b["roof_load"] * KPA]
    frame_weights = [share * w for w in b["elf"]["weights"]]
    for f in range(1, n + 1):
        m = frame_weights[f - 1] / G
        masses.append({"node": 100 * f + 1, "mass": m / 2.0})
        masses.append({"node": 100 * f + 3, "mass": m / 2.0})
        constraints.append({"type": "equal_dof", "master": 100 * f + 3,
                            "slave": 100 * f + 9, "dofs": ["ux"]})
        column_load = q[f - 1] * bay / 2.0 * BEAM_COLUMN_TRIBUTARY_WIDTH
        leaning_load = frame_weights[f - 1] - 2.0 * column_load
        loads.append({"node": 100 * f + 1, "force": [0, 0, -column_load, 0, 0, 0]})
        loads.append({"node": 100 * f + 3, "force": [0, 0, -column_load, 0, 0, 0]})
        loads.append({"node": 100 * f + 9, "force": [0, 0, -leaning_load, 0, 0, 0]})
    for f in range(1, n + 1):
        col = columns[f - 1]["shape"]
        beam = beams[f - 1]["shape"]
        sections.setdefault(col, section_entry(col))
        sections.setdefault(beam, section_entry(beam))
        for line in (1, 3):
            elements.append({"id": 100 * f + line, "type": "elastic_beam",
                             "nodes": [100 * (f - 1) + line, 100 * f + line],
                             "section": col, "geometry": "pdelta"})
        elements.append({"id": 1000 + 100 * f + 1, "type": "elastic_beam",
                         "nodes": [100 * f + 1, 100 * f + 2], "section": beam,
                         "geometry": "linear"})
        elements.append({"id": 1000 + 100 * f + 2, "type": "elastic_beam",
                         "nodes": [100 * f + 2, 100 * f + 3], "section": beam,
                         "geometry": "linear"})
        brace_path = "braces/%s.json" % braces[f - 1]["name"]
        elements.append({"id": 2000 + 100 * f + 1, "type": "brb",
                         "nodes": [100 * (f - 1) + 1, 100 * f + 2], "brace": brace_path,
                         "fidelity": "auto", "mode": "condensed"})
        elements.append({"id": 2000 + 100 * f + 2, "type": "brb",
                         "nodes": [100 * (f - 1) + 3, 100 * f + 2], "brace": brace_path,
                         "fidelity": "auto", "mode": "condensed"})
        elements.append({"id": 3000 + 100 * f, "type": "elastic_beam",
                         "nodes": [100 * (f - 1) + 9, 100 * f + 9], "section": "LEANING",
                         "geometry": "pdelta"})
    stories = [{"name": str(f), "bottom": 100 * (f - 1) + 1, "top": 100 * f + 1}
               for f in range(1, n + 1)]
    floors = [{"name": str(f), "node": 100 * f + 1} for f in range(1, n + 1)]
    model = {
        "title": b["title"],
        "units": {"length": "mm", "force": "N", "mass": "tonne"},
        "dimension": 2,
        "nodes": nodes, "supports": supports, "constraints": constraints, "masses": masses,
        "sections": sections, "materials": {}, "elements": elements,
        "gravity": {"from_masses": False, "loads": loads, "steps": 10},
        "damping": DAMPING, "analysis": ANALYSIS,
        "ground_motion": {"directions": ["x"]},
        "stories": stories, "floors": floors, "recorders": RECORDERS,
        "design": design_block(b, share, braces, beams, columns,
                               {"plan": b["plan"], "floor_load_kPa": b["floor_load"],
                                "roof_load_kPa": b["roof_load"],
                                "braced_bays_per_direction": b["braced_bays_per_direction"]}),
    }
    return model, braces, beams, columns


# 3D: frames on the perimeter, each the middle bay of its side.
def frames_3d(b):
    ax, ay = b["plan"]
    bay = b["bay"]
    return [  # name, direction of the frame's plane, first column's xy, unit vector along the bay
        ("S", "x", ((ax - bay) / 2.0, 0.0), (1.0, 0.0)),
        ("N", "x", ((ax - bay) / 2.0, ay), (1.0, 0.0)),
        ("W", "y", (0.0, (ay - bay) / 2.0), (0.0, 1.0)),
        ("E", "y", (ax, (ay - bay) / 2.0), (0.0, 1.0)),
    ]


def accidental_torsion_share(b, direction):
    """Share of the building's storey shear on one of the two frames of `direction`: half of
    it plus the accidental torsion of ASCE 7-16 12.8.4.2 (centre of mass displaced by 5 % of
    the plan dimension perpendicular to the force; all four frames of equal stiffness k,
    torsional stiffness sum k d^2)."""
    ax, ay = b["plan"]
    d_x, d_y = ay / 2.0, ax / 2.0  # distances of the X frames and of the Y frames from the centre
    j = 2.0 * d_x ** 2 + 2.0 * d_y ** 2
    if direction == "x":
        e, d = 0.05 * ay, d_x
    else:
        e, d = 0.05 * ax, d_y
    return 0.5 + e * d / j


def model_3d(b):
    ax, ay = b["plan"]
    bay = b["bay"]
    n = len(b["storey_heights"])
    levels = [0.0] + b["elf"]["levels"]
    q = [b["floor_load"] * KPA] * (n - 1) + [b["roof_load"] * KPA]
    designs = {}
    for direction in ("x", "y"):
        share = accidental_torsion_share(b, direction)
        designs[direction] = (share,) + frame_members(
            b, share, b["elf"]["shears"],
            lambda i, d=direction: "%s_%s_story%d" % (b["name"], d, i + 1))
    nodes, supports, constraints, masses, elements, loads = [], [], [], [], [], []
    sections = {"LEANING": LEANING_SECTION}
    cx, cy = ax / 2.0, ay / 2.0

    def nid(f, frame_index, line):
        return 1000 * f + 10 * (frame_index + 1) + line

    def master(f):
        return 1000 * f + 99

    for f in range(n + 1):
        nodes.append({"id": master(f), "xyz": [cx, cy, levels[f]]})
    supports.append({"node": master(0), "fix": ["ux", "uy", "uz", "rz"]})
    for fi, (name, direction, (x0, y0), (ux, uy)) in enumerate(frames_3d(b)):
        for f in range(n + 1):
            for line, offset in ((1, 0.0), (2, bay / 2.0), (3, bay)):
                if f == 0 and line == 2:
                    continue
                nodes.append({"id": nid(f, fi, line),
                              "xyz": [x0 + ux * offset, y0 + uy * offset, levels[f]]})
        supports.append({"node": nid(0, fi, 1), "fix": "fixed"})
        supports.append({"node": nid(0, fi, 3), "fix": "fixed"})
        _, braces, beams, columns = designs[direction]
        for f in range(1, n + 1):
            col = columns[f - 1]["shape"]
            beam = beams[f - 1]["shape"]
            sections.setdefault(col, section_entry(col))
            sections.setdefault(beam, section_entry(beam))
            for line in (1, 3):
                column = {"id": 10000 * (fi + 1) + 100 * f + line, "type": "elastic_beam",
                          "nodes": [nid(f - 1, fi, line), nid(f, fi, line)], "section": col,
                          "geometry": "pdelta"}
                if direction == "y":
                    # Columns of a Y frame bend in the Y-Z plane: local z along global Y puts
                    # their strong axis (local y) about global X.
                    column["orientation"] = [0.0, 1.0, 0.0]
                elements.append(column)
            for part, (a, c) in enumerate(((1, 2), (2, 3))):
                elements.append({"id": 10000 * (fi + 1) + 1000 + 100 * f + part + 1,
                                 "type": "elastic_beam", "nodes": [nid(f, fi, a), nid(f, fi, c)],
                                 "section": beam, "geometry": "linear"})
            brace_path = "braces/%s.json" % braces[f - 1]["name"]
            for part, line in enumerate((1, 3)):
                elements.append({"id": 10000 * (fi + 1) + 2000 + 100 * f + part + 1,
                                 "type": "brb", "nodes": [nid(f - 1, fi, line), nid(f, fi, 2)],
                                 "brace": brace_path, "fidelity": "auto", "mode": "condensed"})
    frame_count = len(frames_3d(b))
    for f in range(1, n + 1):
        weight = b["elf"]["weights"][f - 1]
        m = weight / G
        izz = m * (ax ** 2 + ay ** 2) / 12.0
        masses.append({"node": master(f), "mass": [m, m, m, 0.0, 0.0, izz]})
        slaves = [nid(f, fi, line) for fi in range(frame_count) for line in (1, 2, 3)]
        constraints.append({"type": "rigid_diaphragm", "master": master(f), "nodes": slaves})
        column_load = q[f - 1] * bay / 2.0 * BEAM_COLUMN_TRIBUTARY_WIDTH
        for fi in range(frame_count):
            for line in (1, 3):
                loads.append({"node": nid(f, fi, line), "force": [0, 0, -column_load, 0, 0, 0]})
        leaning_load = weight - 2.0 * frame_count * column_load
        loads.append({"node": master(f), "force": [0, 0, -leaning_load, 0, 0, 0]})
        elements.append({"id": 90000 + 100 * f, "type": "elastic_beam",
                         "nodes": [master(f - 1), master(f)], "section": "LEANING",
                         "geometry": "pdelta"})
    stories = [{"name": str(f), "bottom": master(f - 1), "top": master(f)}
               for f in range(1, n + 1)]
    floors = [{"name": str(f), "node": master(f)} for f in range(1, n + 1)]
    e = b["elf"]
    sp = e["spectrum"]
    per_direction = {}
    for direction, (share, braces, beams, columns) in designs.items():
        per_direction[direction] = {
            "frames": [fr[0] for fr in frames_3d(b) if fr[1] == direction],
            "frame_share": share,
            "frame_story_shears": [share * v for v in e["shears"]],
            "braces": [{k: v for k, v in br.items() if k != "file"} for br in braces],
            "beams": beams, "columns": columns,
        }
    design = {
        "source": "frames/design.py (ASCE 7-16 ELF; see frames/README.md)",
        "site": dict(SITE), "system": SYSTEM["name"],
        "R": SYSTEM["R"], "Omega0": SYSTEM["Omega0"], "Cd": SYSTEM["Cd"], "Ie": SITE["Ie"],
        "rho": SYSTEM["rho"],
        "Fa": sp["Fa"], "Fv": sp["Fv"], "SMS": sp["SMS"], "SM1": sp["SM1"],
        "SDS": sp["SDS"], "SD1": sp["SD1"], "Ts": sp["Ts"], "TL": SITE["TL"],
        "hn": e["hn"], "Ct": SYSTEM["Ct"], "x": SYSTEM["x"], "Ta": e["Ta"], "Cu": e["Cu"],
        "CuTa": e["CuTa"], "T": e["T"], "Cs": e["Cs"], "Cs_rule": e["Cs_rule"], "k": e["k"],
        "plan": b["plan"], "floor_load_kPa": b["floor_load"], "roof_load_kPa": b["roof_load"],
        "building_seismic_weight": e["W"], "building_V": e["V"],
        "frame_share": 1.0,
        "seismic_weight": e["W"], "floor_weights": e["weights"], "V": e["V"],
        "Cvx": e["Cvx"], "floor_forces": e["forces"], "story_shears": e["shears"],
        "directions": per_direction,
        "units": {"force": "N", "length": "mm", "mass": "tonne", "period": "s"},
    }
    model = {
        "title": b["title"],
        "units": {"length": "mm", "force": "N", "mass": "tonne"},
        "dimension": 3,
        "nodes": nodes, "supports": supports, "constraints": constraints, "masses": masses,
        "sections": sections, "materials": {}, "elements": elements,
        "gravity": {"from_masses": False, "loads": loads, "steps": 10},
        "damping": DAMPING, "analysis": ANALYSIS,
        "ground_motion": {"directions": ["x", "y"]},
        "stories": stories, "floors": floors, "recorders": RECORDERS,
        "design": design,
    }
    return model, designs


# ---------------------------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------------------------
def dumps(value, indent=0):
    """JSON with one line per node, element, load ...: lists of objects and short lists of
    numbers stay on one line, objects open one level."""
    pad = "  " * indent
    if isinstance(value, dict) and value:
        one_line = json.dumps(value)
        if len(one_line) + len(pad) <= 100 and not any(isinstance(v, dict) and v
                                                       for v in value.values()):
            return one_line
        items = ['%s  %s: %s' % (pad, json.dumps(k), dumps(v, indent + 1))
                 for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list) and value:
        one_line = json.dumps(value)
        if len(one_line) + len(pad) <= 100:
            return one_line
        items = [pad + "  " + dumps(v, indent + 1) if isinstance(v, (dict, list))
                 else pad + "  " + json.dumps(v) for v in value]
        if all(isinstance(v, dict) for v in value):
            items = [pad + "  " + json.dumps(v) if len(json.dumps(v)) + len(pad) <= 130
                     else pad + "  " + dumps(v, indent + 1) for v in value]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    return json.dumps(value)


def write(path, value):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    text = dumps(value) + "\n"
    json.loads(text)  # the writer's own check
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def kn(x):
    return x / 1000.0


def tables(b, braces_by_direction, title_suffix=""):
    """Markdown tables of one building's design."""
    e = b["elf"]
    sp = e["spectrum"]
    out = []
    out.append("### %s%s\n" % (b["title"], title_suffix))
    out.append("Plan %.1f m x %.1f m; storey heights %s m (hn = %.2f m); dead load %.1f kPa on "
               "floors, %.1f kPa on the roof; %s.\n" % (
                   b["plan"][0] / 1000, b["plan"][1] / 1000,
                   ", ".join("%.1f" % (h / 1000) for h in b["storey_heights"]), e["hn"] / 1000,
                   b["floor_load"], b["roof_load"], b["frames_text"]))
    out.append("| quantity | value |\n|---|---|")
    rows = [
        ("Ta = Ct hn^x (Ct 0.0731, x 0.75, hn in m)", "%.3f s" % e["Ta"]),
        ("Cu (Table 12.8-1, SD1 >= 0.4)", "%.1f" % e["Cu"]),
        ("Cu Ta (upper limit for a computed period)", "%.3f s" % e["CuTa"]),
        ("T used for design", "%.3f s (= Ta)" % e["T"]),
        ("1.5 Ts", "%.3f s" % (1.5 * sp["Ts"])),
        ("Cs", "%.4f (%s)" % (e["Cs"], e["Cs_rule"])),
        ("Cs upper bound SDS/(R/Ie)", "%.4f" % (sp["SDS"] / SYSTEM["R"])),
        ("Cs lower bounds 0.044 SDS Ie; 0.5 S1/(R/Ie)",
         "%.4f; %.4f" % (0.044 * sp["SDS"], 0.5 * SITE["S1"] / SYSTEM["R"])),
        ("k (Eq 12.8-12)", "%.3f" % e["k"]),
        ("seismic weight W (building)", "%.0f kN (mass %.1f t)" % (kn(e["W"]), e["W"] / G)),
        ("base shear V = Cs W (building)", "%.0f kN" % kn(e["V"])),
    ]
    for r in rows:
        out.append("| %s | %s |" % r)
    out.append("")
    out.append("| level | height (m) | w_x (kN) | C_vx | F_x (kN) | storey shear V_x (kN) |")
    out.append("|---|---|---|---|---|---|")
    for i in range(len(e["levels"])):
        out.append("| %d | %.2f | %.0f | %.4f | %.1f | %.1f |" % (
            i + 1, e["levels"][i] / 1000, kn(e["weights"][i]), e["Cvx"][i], kn(e["forces"][i]),
            kn(e["shears"][i])))
    out.append("")
    for label, (share, braces, beams, columns) in braces_by_direction:
        out.append("%s: frame share of the storey shears %.4f; two chevron braces per storey, "
                   "Pu = share x V_x / (2 cos theta), Asc = Pu / (0.9 x 262 MPa).\n"
                   % (label, share))
        out.append("| storey | frame V_x (kN) | brace L_wp (mm) | cos theta | Pu (kN) | "
                   "Asc req (mm^2) | core plate (mm) | Asc (mm^2) | Py (kN) | L_y (mm) | "
                   "L_conn (mm) | eps at 2x drift | omega | Pmax = beta omega Py (kN) | "
                   "tube (mm) | P_euler casing (kN) | P_e / Pmax | beam | Mu (kNm) | column | "
                   "column Pu / phiPn (kN) |")
        out.append("|" + "---|" * 21)
        for i, br in enumerate(braces):
            length = br["work_point_length"]
            cos_theta = b["bay"] / 2.0 / length
            out.append("| %d | %.1f | %.1f | %.4f | %.1f | %.0f | %g x %g | %.0f | %.1f | %.0f | "
                       "%.1f | %.4f | %.3f | %.1f | %s | %.0f | %.2f | %s | %.1f | %s | "
                       "%.0f / %.0f |" % (
                           i + 1, kn(share * e["shears"][i]), length, cos_theta, kn(br["Pu"]),
                           br["Asc_required"], br["core_width"], br["core_thickness"], br["Asc"],
                           kn(br["Py"]), br["yielding_length"], br["connection_length"],
                           br["core_strain_2x_drift"], br["omega"], kn(br["Pmax"]), br["tube"],
                           kn(br["casing_euler"]), br["casing_euler"] / br["Pmax"],
                           beams[i]["shape"], beams[i]["Mu"] / 1e6, columns[i]["shape"],
                           kn(columns[i]["Pu"]), kn(columns[i]["phiPn"])))
        out.append("")
    return "\n".join(out)


BUILDINGS = {
    "brbf3": {"name": "brbf3", "title": "3-storey planar BRBF (brbf3)",
              "plan": (54000.0, 36000.0), "storey_heights": [4500.0, 4000.0, 4000.0],
              "bay": 9000.0, "floor_load": 4.5, "roof_load": 3.5,
              "braced_bays_per_direction": 4,
              "frames_text": "4 chevron-braced bays per direction (2 per perimeter side); "
                             "the model is one of them, carrying 1/4 of the building's mass"},
    "brbf9": {"name": "brbf9", "title": "9-storey planar BRBF (brbf9)",
              "plan": (45000.0, 45000.0), "storey_heights": [5000.0] + [4000.0] * 8,
              "bay": 9000.0, "floor_load": 4.5, "roof_load": 3.5,
              "braced_bays_per_direction": 6,
              "frames_text": "6 chevron-braced bays per direction (3 per perimeter side); "
                             "the model is one of them, carrying 1/6 of the building's mass"},
    "brbf4_3d": {"name": "brbf4_3d", "title": "4-storey 3D BRBF building (brbf4_3d)",
                 "plan": (45000.0, 27000.0), "storey_heights": [4500.0, 4000.0, 4000.0, 4000.0],
                 "bay": 9000.0, "floor_load": 4.5, "roof_load": 3.5,
                 "frames_text": "one chevron-braced bay in the middle of each perimeter side "
                                "(2 frames per direction), rigid floors; the model is the "
                                "whole building"},
}


def main():
    sp = spectrum()
    md = []
    md.append("Site: %s, site class %s, SS = %.2f g, S1 = %.2f g, TL = %.0f s; risk category "
              "%s, Ie = %.1f. Fa = %.2f, Fv = %.2f (Tables 11.4-1, 11.4-2), SMS = %.3f g, "
              "SM1 = %.3f g, SDS = %.3f g, SD1 = %.3f g, Ts = SD1/SDS = %.3f s. System: %s: "
              "R = %g, Omega0 = %g, Cd = %g, rho = %g.\n" % (
                  SITE["location"], SITE["site_class"], SITE["SS"], SITE["S1"], SITE["TL"],
                  SITE["risk_category"], SITE["Ie"], sp["Fa"], sp["Fv"], sp["SMS"], sp["SM1"],
                  sp["SDS"], sp["SD1"], sp["Ts"], SYSTEM["name"], SYSTEM["R"],
                  SYSTEM["Omega0"], SYSTEM["Cd"], SYSTEM["rho"]))
    for key in ("brbf3", "brbf9"):
        b = BUILDINGS[key]
        b["elf"] = elf(b)
        model, braces, beams, columns = planar_model(b)
        folder = os.path.join(HERE, key)
        for br in braces:
            write(os.path.join(folder, "braces", br["name"] + ".json"), br["file"])
        write(os.path.join(folder, "model.json"), model)
        md.append(tables(b, [("Frame", (model["design"]["frame_share"], braces, beams,
                                        columns))]))
    b = BUILDINGS["brbf4_3d"]
    b["elf"] = elf(b)
    model, designs = model_3d(b)
    folder = os.path.join(HERE, "brbf4_3d")
    for direction in ("x", "y"):
        for br in designs[direction][1]:
            write(os.path.join(folder, "braces", br["name"] + ".json"), br["file"])
    write(os.path.join(folder, "model.json"), model)
    md.append(tables(b, [("X frames (S, N)", designs["x"]), ("Y frames (W, E)", designs["y"])]))
    text = "\n".join(md)
    print(text)
    readme = os.path.join(HERE, "README.md")
    begin, end = "<!-- BEGIN GENERATED by frames/design.py -->", "<!-- END GENERATED -->"
    with open(readme) as f:
        content = f.read()
    if begin in content and end in content:
        head, rest = content.split(begin, 1)
        _, tail = rest.split(end, 1)
        content = head + begin + "\n" + text + "\n" + end + tail
        tmp = readme + ".tmp"
        with open(tmp, "w") as f:
            f.write(content)
        os.replace(tmp, readme)
    else:
        print("design.py: README.md has no generated block; not updated", file=sys.stderr)


if __name__ == "__main__":
    main()
