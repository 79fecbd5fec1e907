"""SLAMMER 1.1's decoupled and coupled analyses, written out independently of seispulse.

A plain-Python transcription of SLAMMER 1.1's public-domain Java (classes
DeCoupledCommon, Decoupled and Coupled of the package slammer.analysis; [SL13]), made
for the tests: it never calls seispulse. It follows the Java step for step and in
SLAMMER's own units (cm, cm/s^2, g = 980.665 cm/s^2, damping as a fraction inside the
time stepping, in percent inside the equivalent-linear update, the reference strain in
percent), with the same order of floating-point operations where that is cheap, so that
its numbers agree with SLAMMER's code to rounding (about 1e-13 relative):

* the one-mode shear-beam response by incremental Newmark (average acceleration), the
  first step from rest with the load increment a[0] and the acceleration from equilibrium;
  HEA = a + (L/Mtot) u'';
* the equivalent-linear loop (``eq``/``eq_property``): effective strain
  0.65 * 1.57 * max|u| / H, Vs = Vs0 / sqrt(1 + gamma/gamma_r), material damping
  0.62 (G/Gmax)^0.1 D_Masing + 1 %, radiation damping recomputed with the new Vs and
  capped at 20 %, the previous material damping 0 at the start (so at least two
  iterations), stop when both relative changes are <= 5 %;
* decoupled sliding (``d_sliding``): the first step at rest, the + dHEA dt^2 / 6 term,
  the end-of-slide step discarded (s_j = s_{j-1}, s'_j = 0);
* coupled sliding (``Coupled``): the modal equation with d1 = 1 - L^2/(M Mtot) while
  sliding, the load -ky g while sliding, the base-force onset test, trapezoidal sliding
  velocity and displacement, and ``slidestop`` (stop fraction, re-integration over the
  fraction, a non-sliding sub-step over the rest) with its locally shadowed acc11/acc22;
* the yield-acceleration table (``residual_mu``): one row down per step when the mass is
  at rest and |s| >= disp(current row); row 2 is therefore in force from the first step.

Sign and polarity: ``accel`` is the record (g) as the user gives it; "normal" polarity,
positive accelerations drive the (downslope, positive) sliding, as in SLAMMER's tables;
the inverse polarity is ``-accel``. SLAMMER's GUI obtains this by passing -scale to both
routines and flipping it back inside Decoupled only; this module does the same inside
(Coupled runs on -accel). ``kmax_g`` is reported with Decoupled's sign for the record as
given (the Coupled routine itself returns the opposite sign).

Provenance (how this module was checked): SLAMMER's sources and the harness that drives
them the way SLAMMER's GUI does were compiled and run as

    w=$(mktemp -d); mkdir -p $w/src/slammer/analysis
    cp Analysis.java Coupled.java DeCoupledCommon.java Decoupled.java RigidBlock.java \\
       $w/src/slammer/analysis/
    # plus a small driver class Harness (reads a CSV record, scales it by target / PGA and
    # calls the routines with the units and signs SLAMMER's GUI uses) and stand-ins for
    # SLAMMER's plotting class, as test/data/slammer/README.md describes
    javac -nowarn -d $w/out $(find $w/src -name '*.java')
    # method csv targetPGA(g) ky(g) H(m) Vs Vs_base(m/s) damping(fraction) refstrain(%)
    #   eql(0/1) polarity(nor/inv); CATAB="d_cm,ky2" adds the table row (d_cm, ky2)
    java -cp $w/out Harness decoupled Cape_Mendocino_1992_PET-090.csv 0.2 0.15 50 600 600 \\
       -0.05 0.05 0 nor
    java -cp $w/out Harness coupled   Cape_Mendocino_1992_PET-090.csv 0.2 0.15 50 600 600 \\
       -0.05 0.05 0 nor
    java -cp $w/out Harness decoupled Kobe_1995_TAK-090.csv 0.4 0.1 300 300 1200 0.1 0.03 1 inv
    java -cp $w/out Harness coupled   Kobe_1995_TAK-090.csv 0.4 0.1 300 300 1200 0.1 0.03 1 inv
    java -cp $w/out Harness decoupled Northridge_1994_PAC-175.csv 0.5 0.05 25 600 600 \\
       -0.2 0.05 0 nor
    java -cp $w/out Harness coupled   Northridge_1994_PAC-175.csv 0.5 0.05 300 400 \\
       1200 -0.2 0.05 0 inv
    CATAB=2,0.08 java -cp $w/out Harness decoupled Duzce_1999_375-090.csv 0.4 0.15 50 400 \\
       600 0.05 0.05 0 nor
    CATAB=2,0.08 java -cp $w/out Harness coupled Duzce_1999_375-090.csv 0.4 0.15 50 400 \\
       600 0.05 0.05 1 nor
    java -cp $w/out Harness decoupled Kocaeli_1999_ATS-090.csv 0.4 0.05 50 600 600 0.05 \\
       0.01 1 nor
    java -cp $w/out Harness coupled   Kocaeli_1999_ATS-090.csv 0.4 0.05 50 600 600 0.05 \\
       0.01 1 nor
    java -cp $w/out Harness decoupled Coyote_Lake_1979_G02-050.csv 0.5 0.05 300 600 600 \\
       -0.05 0.05 0 inv
    java -cp $w/out Harness coupled   Coyote_Lake_1979_G02-050.csv 0.5 0.05 300 600 600 \\
       -0.05 0.05 0 inv

(the records are the CSV files of the PyPI package pyslammer, folder
sample_ground_motions/; the harness scales by target / exact PGA). This module, given
the same record times target / PGA, reproduced the displacement, kmax, final Vs and
final damping of every one of these 12 runs to 2.1e-12 relative or better (the largest
differences in the equivalent-linear Kocaeli runs, 26 780 samples and 5 passes; 1e-14 to
1e-16 elsewhere), and the 108 runs of test/data/slammer/java-flexible.csv to 4e-11 (the
largest on displacements below 0.02 cm).
"""
import math
from collections import namedtuple

#: SLAMMER's standard gravity (cm/s^2), Analysis.Gcmss.
G_CM = 980.665
#: SLAMMER's unit weights: Decoupled overwrites it with 20 (metric); Coupled keeps the
#: GUI's value (100 / 1e6); both cancel out of every result.
_UWGT_DECOUPLED = 20.0
_UWGT_COUPLED = 100.0 / 1.0e6
_BETA = 0.25
_GAMMA = 0.5
#: A guard for the tests only: SLAMMER's loop has no iteration cap.
MAX_EQL_ITERATIONS = 1000

SlammerFlexible = namedtuple(
    "SlammerFlexible",
    "disp_cm kmax_g vs_final_mps damping_final damping_radiation iterations hea_cm disp_hist_cm")
SlammerFlexible.__doc__ = """Result of a SLAMMER decoupled or coupled analysis.

disp_cm: permanent displacement (cm, >= 0); kmax_g: HEA of largest |value| with
Decoupled's sign for the record as given (g); vs_final_mps: Vs of the final response
(m/s); damping_final: total damping of the final response (fraction);
damping_radiation: radiation part (fraction); iterations: equivalent-linear passes (0 for
linear); hea_cm: HEA of the final decoupled response (cm/s^2, record as given);
disp_hist_cm: sliding displacement at the samples (cm)."""


def _jdiv(num, den):
    """num / den with Java's IEEE semantics where den may be 0 (inf or NaN, no error)."""
    if den != 0.0:
        return num / den
    if num == 0.0 or math.isnan(num):
        return math.nan
    return math.copysign(math.inf, num) * math.copysign(1.0, den)


def _signed_peak(values):
    """Value of largest magnitude, SLAMMER's effstr/avg_acc scan: the largest non-negative
    and the smallest negative value, the larger in magnitude, the positive one on a tie."""
    mx1 = mx = values[0]
    for v in values[1:]:
        if v < 0.0:
            if v <= mx1:
                mx1 = v
        elif v >= mx:
            mx = v
    if abs(mx) > abs(mx1):
        return mx
    if abs(mx) < abs(mx1):
        return mx1
    return mx if mx > 0.0 else mx1


class _Beam:
    """The one-mode shear beam of SLAMMER's DeCoupledCommon (units cm, s)."""

    def __init__(self, acc, dt, height_cm, vs_cms, vr_cms, damping, uwgt, decoupled_l):
        self.acc = acc          # base acceleration at the samples (cm/s^2), ain * g * scal
        self.dt = dt
        self.height = height_cm
        self.vs1 = vs_cms       # initial Vs (cm/s)
        self.vs = vs_cms
        self.vr = vr_cms
        self.uwgt = uwgt
        rho = uwgt / G_CM
        self.Mtot = rho * height_cm
        if decoupled_l:
            self.L = -2.0 * rho * height_cm / math.pi * math.cos(math.pi)
        else:
            self.L = 2.0 * rho * height_cm / math.pi
        self.M = rho * height_cm / 2.0
        dampf = 55.016 * math.pow(vr_cms / vs_cms, -0.9904) / 100.0
        if dampf > 0.2:
            dampf = 0.2
        self.dampf = dampf
        self.damp = damping + dampf
        self.iterations = 0

    def response(self):
        """Newmark response with the current (Vs, damping): u (cm), u'' (cm/s^2), HEA."""
        acc, dt = self.acc, self.dt
        damp = self.damp
        L, M, Mtot = self.L, self.M, self.Mtot
        beta, gamma = _BETA, _GAMMA
        omega = math.pi * self.vs / (2.0 * self.height)
        khat = ((omega * omega) + 2.0 * damp * omega * gamma / (beta * dt)
                + 1.0 / (beta * (dt * dt)))
        a = 1.0 / (beta * dt) + 2.0 * damp * omega * gamma / beta
        b = 1.0 / (2.0 * beta) + dt * 2.0 * damp * omega * (gamma / (2.0 * beta) - 1.0)
        c1 = gamma / (beta * dt)
        c2 = gamma / beta
        c3 = dt * (1.0 - gamma / (2.0 * beta))
        c4 = 1.0 / (beta * (dt * dt))
        c5 = 1.0 / (beta * dt)
        c6 = 0.5 / beta
        lm = L / M
        lmt = L / Mtot
        n = len(acc)
        u = [0.0] * n
        hea = [0.0] * n
        # first step from rest, load increment a[0] - 0, u'' from equilibrium (D-1)
        acc2 = acc[0]
        deltu = (-L / M * (acc2 - 0.0)) / khat
        u2 = deltu
        ud2 = c1 * deltu
        udd2 = -lm * acc2 - 2.0 * damp * omega * ud2 - (omega * omega) * u2
        u[0] = u2
        hea[0] = acc2 + lmt * udd2
        for j in range(1, n):
            u1, ud1, udd1 = u2, ud2, udd2
            acc1 = acc2
            acc2 = acc[j]
            deltp = -L / M * (acc2 - acc1) + a * ud1 + b * udd1
            deltu = deltp / khat
            deltud = c1 * deltu - c2 * ud1 + c3 * udd1
            deltudd = c4 * deltu - c5 * ud1 - c6 * udd1
            u2 = u1 + deltu
            ud2 = ud1 + deltud
            udd2 = udd1 + deltudd
            u[j] = u2
            hea[j] = acc2 + lmt * udd2
        return u, hea

    def equivalent_linear(self, ref_strain_pct):
        """SLAMMER's eq() loop; leaves the converged Vs and damping in self."""
        gamref = ref_strain_pct
        damps_prev = 0.0
        n_chg = o_chg = 100.0
        while n_chg > 5.0 or o_chg > 5.0:
            if self.iterations >= MAX_EQL_ITERATIONS:
                raise RuntimeError("SLAMMER's equivalent-linear loop did not converge")
            self.iterations += 1
            u, _ = self.response()
            gameff1 = abs(0.65 * 1.57 * _signed_peak(u) / self.height)
            # eq_property
            gameff2 = abs(gameff1) * 100.0
            vs2 = self.vs1 / math.sqrt(1.0 + (gameff2 / gamref))
            com1 = 1.0 / (1.0 + gameff2 / gamref)
            com2 = math.pow(com1, 0.1)
            dampf = 55.016 * math.pow(self.vr / vs2, -0.9904)
            if dampf > 20.0:
                dampf = 20.0
            damps = 0.62 * com2 * (100.0 / math.pi * (4.0 * (
                (gameff2 - gamref * math.log((gamref + gameff2) / gamref))
                / (gameff2 * gameff2 / (gameff2 + gamref))) - 2.0)) + 1.0
            damp2 = dampf + damps
            g1 = (self.uwgt / G_CM) * self.vs * self.vs
            g2 = (self.uwgt / G_CM) * vs2 * vs2
            chg_l = (g1 - g2) / g1
            chg_m = _jdiv(damps_prev - damps, damps_prev)
            n_chg = abs(chg_l) * 100.0
            o_chg = abs(chg_m) * 100.0
            self.vs = vs2
            damps_prev = damps
            self.damp = damp2 * 0.01
            self.dampf = dampf * 0.01


def _table(ky, ky_table):
    """SLAMMER's (disp cm, ky g) rows: [(0, ky)] or the user's table (disp m -> cm)."""
    if ky_table is None:
        return [0.0], [float(ky)]
    disp_m, values = ky_table
    if len(disp_m) != len(values) or len(values) < 1:
        raise ValueError("ky_table: displacements and values of the same size >= 1")
    return [float(d) * 100.0 for d in disp_m], [float(v) for v in values]


def _beam(acc_cm, dt, height, vs, vs_base, damping, soil, ref_strain_pct, uwgt, dec):
    if soil not in ("linear", "equivalent_linear"):
        raise ValueError("soil must be 'linear' or 'equivalent_linear'")
    beam = _Beam(acc_cm, float(dt), float(height) * 100.0, float(vs) * 100.0,
                 float(vs_base) * 100.0, float(damping), uwgt, dec)
    if soil == "equivalent_linear":
        beam.equivalent_linear(float(ref_strain_pct))
    return beam


def decoupled(accel, dt, ky, height, vs, vs_base, damping, soil="linear",
              ref_strain_pct=0.05, ky_table=None):
    """SLAMMER 1.1's Decoupled on ``accel`` (g, samples dt s apart, normal polarity).

    ky (g) or ky_table = (disp m, ky g); height (m); vs, vs_base (m/s); damping
    (fraction, SLAMMER's percent / 100); soil 'linear' | 'equivalent_linear';
    ref_strain_pct (percent). Returns :class:`SlammerFlexible`.
    """
    acc = [float(x) * G_CM for x in accel]     # Decoupled: scal flipped back, record as given
    beam = _beam(acc, dt, height, vs, vs_base, damping, soil, ref_strain_pct,
                 _UWGT_DECOUPLED, True)
    _, hea = beam.response()
    kmax = _signed_peak(hea)
    disp, mu = _table(ky, ky_table)
    nmu = len(mu)
    dt = float(dt)
    g = G_CM
    n = len(hea)
    s = [0.0] * n
    sdot = [0.0] * n
    slide = False
    qq = 1
    for j in range(1, n + 1):
        # d_sliding
        if j == 1:
            deltacc = hea[0]
            sdot[0] = 0.0
            s[0] = 0.0
        else:
            deltacc = hea[j - 1] - hea[j - 2]
            if not slide:
                sdot[j - 1] = 0.0
                s[j - 1] = s[j - 2]
            else:
                e = mu[qq - 1] * g - hea[j - 2]
                sdot[j - 1] = sdot[j - 2] + e * dt - 0.5 * deltacc * dt
                s[j - 1] = (s[j - 2] - sdot[j - 2] * dt - 0.5 * dt * dt * e
                            + deltacc * dt * dt / 6.0)
        if not slide:
            if hea[j - 1] > mu[qq - 1] * g:
                slide = True
        elif sdot[j - 1] >= 0.0:
            slide = False
            s[j - 1] = 0.0 if j == 1 else s[j - 2]
            sdot[j - 1] = 0.0
        # residual_mu
        if nmu > 1 and not slide and abs(s[j - 1]) >= disp[qq - 1] and qq <= nmu - 1:
            qq += 1
    return SlammerFlexible(abs(s[n - 1]), kmax / G_CM, beam.vs / 100.0, beam.damp,
                           beam.dampf, beam.iterations, hea, s)


def coupled(accel, dt, ky, height, vs, vs_base, damping, soil="linear",
            ref_strain_pct=0.05, ky_table=None):
    """SLAMMER 1.1's Coupled on ``accel`` (g, samples dt s apart, normal polarity).

    Arguments and result as :func:`decoupled`; the slope angle is 0 as in SLAMMER.
    """
    g = G_CM
    ain = [-float(x) for x in accel]            # the GUI passes -scale; Coupled keeps it
    acc = [x * g for x in ain]
    beam = _beam(acc, dt, height, vs, vs_base, damping, soil, ref_strain_pct,
                 _UWGT_COUPLED, False)
    _, hea = beam.response()
    kmax = -_signed_peak(hea)                    # Decoupled's sign for the record as given
    disp, mu = _table(ky, ky_table)
    nmu = len(mu)
    dt = float(dt)
    L, M, Mtot = beam.L, beam.M, beam.Mtot
    damp = beam.damp
    omega = math.pi * beam.vs / (2.0 * beam.height)
    beta, gamma = _BETA, _GAMMA
    gcos, gsin, cos_, sin_ = g, 0.0, 1.0, 0.0   # angle = 0

    def solvu(j, slide, u1, ud1, udd1, acc11, acc22):
        d1 = 1.0 - (L * L) / (M * Mtot) if slide else 1.0
        khat = ((omega * omega) + 2.0 * damp * omega * gamma / (beta * dt)
                + d1 / (beta * (dt * dt)))
        a = d1 / (beta * dt) + 2.0 * damp * omega * gamma / beta
        b = d1 / (2.0 * beta) + dt * 2.0 * damp * omega * (gamma / (2.0 * beta) - 1.0)
        if j == 1:
            deltp = -L / M * (acc22 - acc11)
            deltu = deltp / khat
            u2 = deltu
            ud2 = gamma / (beta * dt) * deltu
        else:
            deltp = -L / M * (acc22 - acc11) + a * ud1 + b * udd1
            deltu = deltp / khat
            deltud = (gamma / (beta * dt) * deltu - gamma / beta * ud1
                      + dt * (1.0 - gamma / (2.0 * beta)) * udd1)
            u2 = u1 + deltu
            ud2 = ud1 + deltud
        udd2 = (-(L / M) * acc22 - 2.0 * damp * omega * ud2 - (omega * omega) * u2) / d1
        return u2, ud2, udd2

    n = len(ain)
    s_hist = [0.0] * n
    slide = False
    qq = 1
    u2 = ud2 = udd2 = 0.0
    s2 = sd2 = sdd2 = 0.0
    nf2 = 0.0
    for j in range(1, n + 1):
        # coupled_setupstate
        if j == 1:
            u1 = ud1 = udd1 = 0.0
            s1 = sd1 = sdd1 = 0.0
            nf1 = 0.0
        else:
            u1, ud1, udd1 = u2, ud2, udd2
            s1, sd1, sdd1 = s2, sd2, sdd2
            nf1 = nf2
        nf2 = Mtot * gcos + Mtot * ain[j - 1] * 1.0 * gsin
        if j == 1:
            acc11 = 0.0
            acc22 = ain[0] * gcos * 1.0
        elif not slide:
            acc11 = ain[j - 2] * gcos * 1.0
            acc22 = ain[j - 1] * gcos * 1.0
        else:
            acc11 = gsin - mu[qq - 1] * nf1 / Mtot
            acc22 = gsin - mu[qq - 1] * nf2 / Mtot
        u2, ud2, udd2 = solvu(j, slide, u1, ud1, udd1, acc11, acc22)
        # c_slideacc
        if slide:
            sdd2 = (-ain[j - 1] * gcos * 1.0 - mu[qq - 1] * nf2 / Mtot - L * udd2 / Mtot
                    + gsin)
        basef = -Mtot * ain[j - 1] * gcos * 1.0 - L * udd2 + Mtot * gsin
        if slide:
            sd2 = sd1 + 0.5 * dt * (sdd2 + sdd1)
            s2 = s1 + 0.5 * dt * (sd2 + sd1)
        # c_slidingcheck
        if not slide:
            if basef > mu[qq - 1] * nf2:
                slide = True
        elif sd2 <= 0.0:
            # slidestop: the stop fraction dd of the step, sliding over dd dt, then a
            # non-sliding sub-step over (1 - dd) dt (its acc11/acc22 are local)
            dd = _jdiv(-sd1, sd2 - sd1)
            if not dd == 0.0:
                ddt = dd * dt
                acc1b = ain[j - 2] * g * 1.0 + dd * (ain[j - 1] - ain[j - 2]) * g * 1.0
                l_acc22 = gsin - mu[qq - 1] * (gcos + acc1b * sin_)
                u2, ud2, udd2 = solvu(j, True, u1, ud1, udd1, acc11, acc22)
                u1, ud1, udd1 = u2, ud2, udd2
                nf2 = Mtot * gcos + Mtot * acc1b * sin_
                sdd2 = -acc1b * cos_ - mu[qq - 1] * nf2 / Mtot - L * udd2 / Mtot + gsin
                sd2 = sd1 + 0.5 * ddt * (sdd2 + sdd1)
                s2 = s1 + 0.5 * ddt * (sd1 + sd2)
                ddt = (1.0 - dd) * dt
                l_acc11 = l_acc22
                l_acc22 = ain[j - 1] * gcos * 1.0
                khat = (1.0 + 2.0 * damp * omega * gamma * ddt
                        + (omega * omega) * beta * (ddt * ddt))
                a = ((1.0 - (L * L) / (Mtot * M)) + 2.0 * damp * omega * ddt * (gamma - 1.0)
                     + (omega * omega) * (ddt * ddt) * (beta - 0.5))
                b = (omega * omega) * ddt
                deltp = -L / M * (l_acc22 - l_acc11) + a * udd1 - b * ud1
                udd2 = deltp / khat
                ud2 = ud1 + (1.0 - gamma) * ddt * udd1 + gamma * ddt * udd2
                u2 = (u1 + ud1 * ddt + (0.5 - beta) * (ddt * ddt) * udd1
                      + beta * (ddt * ddt) * udd2)
            slide = False
            sd2 = 0.0
            sdd2 = 0.0
        s_hist[j - 1] = s2
        # residual_mu
        if nmu > 1 and not slide and abs(s_hist[j - 1]) >= disp[qq - 1] and qq <= nmu - 1:
            qq += 1
    hea_given = [-h for h in hea]
    return SlammerFlexible(abs(s2), kmax / g, beam.vs / 100.0, beam.damp, beam.dampf,
                           beam.iterations, hea_given, s_hist)
