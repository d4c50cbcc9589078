#!/usr/bin/env python3
"""Reconstruct the drained triaxial curves of the loose Yakutat sand.

The original records (Albatal 2018, the paper's Fig. 3) are not public. These
curves are built only from the properties the paper reports (section 3.2,
Table 1): cell pressure 1.72 kPa, D_r = 0 % and 15 %, peak friction angle
38-40 deg, critical-state angle 32 deg, E' = 1000-5000 kPa. They are NOT
measurements. The shape is deliberately not the SSMC law the calibration
fits: a hyperbolic (Kondner) rise towards the peak multiplied by a smooth
Gaussian-type softening onto the critical state, plus 1 % seeded noise.

Run: python3 data/lab/make_lab_curves.py   (stdlib only; rewrites the CSVs)
"""
import math
import random

CELL_PRESSURE_KPA = 1.72


def n_phi(phi_deg):
    s = math.sin(math.radians(phi_deg))
    return (1 + s) / (1 - s)


def curve(eps, E_kPa, phi_peak_deg, phi_crit_deg, eps_peak, softening_width, psi_deg):
    q_peak = CELL_PRESSURE_KPA * (n_phi(phi_peak_deg) - 1)
    q_crit = CELL_PRESSURE_KPA * (n_phi(phi_crit_deg) - 1)
    # Kondner hyperbola with initial slope E' that reaches q_peak at eps_peak.
    # q = eps / (1/E + eps/q_ult): choose q_ult so that q(eps_peak) = q_peak.
    q_ult = eps_peak / (eps_peak / q_peak - 1.0 / E_kPa)
    rise = eps / (1.0 / E_kPa + eps / q_ult)
    if eps <= eps_peak:
        q = rise
    else:
        # Softening: a Gaussian-type fall from the peak to the critical state
        # (zero slope at the peak, so the curve stays smooth there).
        x = (eps - eps_peak) / softening_width
        q = q_crit + (q_peak - q_crit) * math.exp(-x * x)
    # Volumetric strain (compression positive): elastic-like contraction, then
    # dilation at rate tan(psi)-ish after the phase-transformation strain.
    eps_pt = 0.4 * eps_peak
    contraction = 0.25 * eps_peak * (1 - math.exp(-eps / (0.3 * eps_peak)))
    dilation_rate = 2 * math.sin(math.radians(psi_deg)) / (1 - math.sin(math.radians(psi_deg)))
    # The dilation rate fades after the peak so the volume stops changing at
    # the critical state: integral of rate * exp(-(e - eps_peak)/w) de.
    w = softening_width
    if eps <= eps_pt:
        dilated = 0.0
    elif eps <= eps_peak:
        dilated = eps - eps_pt
    else:
        dilated = (eps_peak - eps_pt) + w * (1 - math.exp(-(eps - eps_peak) / w))
    dilation = dilation_rate * dilated
    return q, contraction - dilation


def write(name, relative_density, E_kPa, phi_peak_deg, eps_peak, softening_width, psi_deg, seed):
    rng = random.Random(seed)
    rows = []
    eps = 0.0
    while eps <= 0.20 + 1e-12:
        q, ev = curve(eps, E_kPa, phi_peak_deg, 32.0, eps_peak, softening_width, psi_deg)
        noise = 1 + 0.01 * rng.uniform(-1, 1) if eps > 0 else 1
        rows.append((eps, q * noise, ev))
        eps += 0.0025 if eps < 0.04 else 0.005
    with open(name, "w") as f:
        f.write(f"# Reconstructed drained triaxial curve, NOT a measurement (see README.md).\n")
        f.write(f"# sigma3 = {CELL_PRESSURE_KPA} kPa, D_r = {relative_density}, E' = {E_kPa} kPa, "
                f"phi_peak = {phi_peak_deg} deg, phi_crit = 32 deg, psi ~ {psi_deg} deg\n")
        f.write("axial_strain,deviatoric_stress_kPa,volumetric_strain\n")
        for e, q, ev in rows:
            f.write(f"{e:.5f},{q:.4f},{ev:.6f}\n")


if __name__ == "__main__":
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    write(os.path.join(here, "triaxial_dr00.csv"), 0.00, 1000.0, 38.0, 0.045, 0.060, 2.0, seed=1)
    write(os.path.join(here, "triaxial_dr15.csv"), 0.15, 5000.0, 40.0, 0.025, 0.035, 5.0, seed=2)
