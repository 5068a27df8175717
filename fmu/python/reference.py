"""Independent reference calculation of the FMU physics without spin.

Written from the report, not from the Rust code: circular Hertz contact in
closed form (a^3 = 3 N R / (4 E*), P0 = 3 N / (2 pi a^2)) and the J+T
elastic/plastic traction in the form printed in Appendix V, eq. 22-23:

    J1 = (3 pi/8)(m/mu)(dU/U)sqrt(k),  S = (2/3) sqrt(J1^2 + J2^2)/sqrt(k)
    psi = (1/pi)[pi/2 - asin((1-S^2)/(1+S^2)) + 2S/(1+S^2)]
    J4 = (2/3) J1 psi/(S sqrt(k)),     Fx = mu N J4

with U replaced by max(|U|, U_reg) (the FMU's documented regularisation;
traction-contact blends the forward and reversed rolling solutions within
|U| < U_reg, which without spin gives the same forces).
"""

import math

# Parameters the tests give the FMU: a ball-like crowned roller (rx1 = ry1)
# on a flat (rx2 = ry2 = 0), so the contact is circular (k = 1).
PARAMS = {
    "rx1": 0.02,
    "ry1": 0.02,
    "rx2": 0.0,
    "ry2": 0.0,
    "e1": 2.07e11,
    "nu1": 0.3,
    "e2": 2.07e11,
    "nu2": 0.3,
    "rolling_radius1": 0.02,
    "rolling_radius2": 0.05,
    "m_user": 35.0,
    "mu_user": 0.075,
    "rolling_speed_regularisation": 0.01,
}


def hertz_circular(load, p=PARAMS):
    """Semi-axis a (m) and P0 (Pa) of the circular contact."""
    e_star = 1.0 / ((1 - p["nu1"] ** 2) / p["e1"] + (1 - p["nu2"] ** 2) / p["e2"])
    r = p["rx1"]  # 1/R = 1/rx1 + 1/rx2(flat) along both axes
    a = (3.0 * load * r / (4.0 * e_star)) ** (1.0 / 3.0)
    return a, 3.0 * load / (2.0 * math.pi * a * a)


def traction(load, omega1, omega2, dv=0.0, p=PARAMS):
    """Fx, Fy (N) on body 2 for the given angular speeds (rad/s)."""
    if load <= 0:
        return 0.0, 0.0
    u1 = omega1 * p["rolling_radius1"]
    u2 = omega2 * p["rolling_radius2"]
    u = max(abs(0.5 * (u1 + u2)), p["rolling_speed_regularisation"])
    du = u1 - u2
    m, mu, k = p["m_user"], p["mu_user"], 1.0
    j1 = 3 * math.pi / 8 * (m / mu) * (du / u) * math.sqrt(k)
    j2 = 3 * math.pi / 8 * (m / mu) * (dv / u) * math.sqrt(k)
    s = 2.0 / 3.0 * math.hypot(j1, j2) / math.sqrt(k)
    if s == 0.0:
        return 0.0, 0.0
    psi = (math.pi / 2 - math.asin((1 - s * s) / (1 + s * s)) + 2 * s / (1 + s * s)) / math.pi
    j4 = 2.0 / 3.0 * j1 * psi / (s * math.sqrt(k))
    j5 = 2.0 / 3.0 * j2 * psi / (s * math.sqrt(k))
    return mu * load * j4, mu * load * j5


def slip_for_traction(load, u, fx, p=PARAMS):
    """Inverse of the traction curve: dU (m/s) giving Fx at rolling speed U."""
    lo, hi = 0.0, u
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        # omega1, omega2 that give rolling speed u and slip mid
        w1 = (u + mid / 2) / p["rolling_radius1"]
        w2 = (u - mid / 2) / p["rolling_radius2"]
        if traction(load, w1, w2)[0] < fx:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
