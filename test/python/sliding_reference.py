"""Independent high-precision oracle for the half- and full-cycle sliding block: the
chapter's own closed forms (doc/sliding.md Eqs. 1.7, 1.8, 1.9, 1.12, 1.13, 1.18, the
corrected 1.19, 1.23 and the corrected 1.24; doc/sliding.md sections 3-5) evaluated with
mpmath at 150 digits, where their cancellations are harmless. The library uses none of
these expansions (it integrates Eq. 1.5 with the ground primitives), so agreement
checks both. Symmetric friction, no static factor, finite beta != 0.
"""
from mpmath import mp, mpf, exp, log

# e^(2 beta (1 - tau_m)) in 1.9 reaches 1e90 for beta = -2 pi, eta = 0.05; every public
# function works at this precision whatever other modules set mp.dps to
DPS = 150


def H(x):
    return 1 if x > 0 else 0


def tau_y(eta, b):
    """Eq. 1.12."""
    return log(1 - eta * (1 - exp(b))) / (2 * b)


def tau_m_free(ty, eta, b):
    """Eq. 1.7."""
    return ty + (1 + (1 + exp(2 * b * ty)) / (2 * b) - exp(b) / b - ty) / (eta * (1 - exp(b)))


def eq_1_8(tm, ty, eta, b):
    return (tm - ty) * (1 - eta * (1 - exp(b))) + (exp(2 * b * (1 - tm)) + exp(2 * b * ty)
                                                   - 2 * exp(b)) / (2 * b)


def eq_1_19(tm, ty, eta, b):
    """Corrected 1.19a (doc/sliding.md section 4)."""
    y = eq_1_8(tm, ty, eta, b)
    y += (2 * (1 - tm) + (exp(-2 * b * (1 - tm)) - exp(2 * b * (1 - tm))) / (2 * b)) * H(tm - 1)
    y += (2 * exp(b) - exp(2 * b * (2 - tm)) - exp(-2 * b * (1 - tm))) / (2 * b) * H(tm - mpf(3) / 2)
    return y


def bisect(f, lo, hi, n=200):
    flo = f(lo)
    for _ in range(n):
        mid = (lo + hi) / 2
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return (lo + hi) / 2


def x1(tm, ty, eta, b):
    """Eq. 1.9b."""
    return (-exp(2 * b * (1 - tm)) + exp(2 * b * ty)
            + 2 * b * (exp(b) * (1 - 2 * tm) + exp(2 * b * ty) * (tm - ty))
            + 2 * b ** 2 * (tm - ty) ** 2 * (1 - eta * (1 - exp(b))))


def um_half(tm, ty, eta, b):
    """Eq. 1.9a."""
    u = x1(tm, ty, eta, b) + (-2 * b * (1 - tm) * (1 + b * (1 - tm)) - 1
                              + exp(2 * b * (1 - tm))) * H(tm - 1)
    return u / (4 * b ** 2 * (1 - exp(b)))


def um_full(tm, ty, eta, b):
    """Eq. 1.18."""
    u = x1(tm, ty, eta, b)
    u += (exp(2 * b * (1 - tm)) + exp(-2 * b * (1 - tm)) - 2 - 4 * b ** 2 * (1 - tm) ** 2) * H(tm - 1)
    u += (exp(2 * b * (2 - tm)) - exp(-2 * b * (1 - tm)) + 2 * b * exp(b) * (2 * tm - 3)) * H(tm - mpf(3) / 2)
    return u / (4 * b ** 2 * (1 - exp(b)))


def vm_ratio(eta, b):
    """Eq. 1.13."""
    ty = tau_y(eta, b)
    return ((1 - eta) * (exp(b) - 1) - b * (1 + eta * (exp(b) - 1)) * (1 - 2 * ty)) / (exp(b) - b - 1)


def half_slide(ty, eta, b):
    """Stop and slip of a slide starting at ty <= 1/2 (1.7, else 1.8; then 1.9)."""
    tm = tau_m_free(ty, eta, b)
    if tm <= 1:
        t_k = 1 - tau_y(eta, b)
        tm = bisect(lambda t: eq_1_8(t, ty, eta, b), t_k, mpf(1))
    return tm, um_half(tm, ty, eta, b)


def late_slide(tyb, eta, b):
    """Slip with a reverse onset tyb > 1/2: Eq. 1.23 and the corrected 1.24."""
    tmb = tyb + (1 + (1 - exp(2 * b * (1 - tyb))) / (2 * b) - tyb) / (eta * (1 - exp(b)))
    u = (-2 * b ** 2 * ((1 - tyb) * (1 + tyb - 2 * tmb) + eta * (tmb - tyb) ** 2)
         + 2 * b ** 2 * exp(b) * eta * (tmb - tyb) ** 2
         + exp(2 * b * (1 - tyb)) * (1 - 2 * b * (tmb - tyb)) - 2 * b * (1 - tmb) - 1)
    return tmb, u / (4 * b ** 2 * (1 - exp(b)))


@mp.workdps(DPS)
def printed_1_24(tyb, tmb, eta, b):
    """Eq. 1.24 as printed, with e^(beta (1 + 2 tyb)) (doc/sliding.md Corrections 5)."""
    u = (-2 * b ** 2 * ((1 - tyb) * (1 + tyb - 2 * tmb) + eta * (tmb - tyb) ** 2)
         + 2 * b ** 2 * exp(b * (1 + 2 * tyb)) * eta * (tmb - tyb) ** 2
         + exp(2 * b * (1 - tyb)) * (1 - 2 * b * (tmb - tyb)) - 2 * b * (1 - tmb) - 1)
    return u / (4 * b ** 2 * (1 - exp(b)))


@mp.workdps(DPS)
def half_cycle(eta, beta):
    eta, b = mpf(eta), mpf(beta)
    ty = tau_y(eta, b)
    tm, um = half_slide(ty, eta, b)
    return {"tau_y": ty, "tau_m": tm, "um": um, "vm": vm_ratio(eta, b)}


@mp.workdps(DPS)
def full_cycle(eta, beta):
    """Symmetric full cycle by Table 1.1 (stick/slip criterion 1.21)."""
    eta, b = mpf(eta), mpf(beta)
    ty = tau_y(eta, b)
    tm1 = bisect(lambda t: eq_1_19(t, ty, eta, b), 1 - ty, 2 - ty)
    um1 = um_full(tm1, ty, eta, b)
    if tm1 <= 1 + ty:
        mode, tyb = "stick", ty
    else:
        mode, tyb = "slip", tm1 - 1
    if tyb <= mpf(1) / 2:
        tmb, um2 = half_slide(tyb, eta, b)
    else:
        tmb, um2 = late_slide(tyb, eta, b)
    return {"mode": mode, "tau_y1": ty, "tau_m1": tm1, "um1": um1, "tau_y2": 1 + tyb,
            "tau_m2": 1 + tmb, "um2": um2, "ures": um1 - um2}
