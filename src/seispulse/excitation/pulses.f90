!> Idealized ground-motion pulses: acceleration, velocity and displacement in
!> closed form.
!>
!> Every pulse starts from rest: a = v = d = 0 for t < 0, and v, d are the exact
!> integrals of a from t = 0. Acceleration is right-continuous at a jump.
!>
!> 1. The generalized exponential pulse of Jacobsen & Ayre (doc/pulses.md Eq. 1.1b,
!>    doc/pulses.md Corrections: Eq. 1.1a has the sign of beta flipped), dimensionless:
!>    tau = t/t_d, a in A_g, v in A_g t_d, d in A_g t_d^2. On the rising half of a
!>    lobe, 0 <= s <= 1/2, with x = 2 beta s and phi_k of seispulse_special:
!>        a = 2 s phi_1(x)/phi_1(beta),   v = 2 s^2 phi_2(x)/phi_1(beta),
!>        d = 2 s^3 phi_3(x)/phi_1(beta),  V_g/(A_g t_d) = phi_2(beta)/phi_1(beta),
!>    which equal the printed (1 - e^(2 beta s))/(1 - e^beta), c[s - (e^x - 1)/(2 beta)],
!>    ... of doc/pulses.md section 1 but are exact at beta = 0 (triangle) and lose no digits
!>    for tiny |beta|. The falling half and the negative lobe of the full cycle
!>    follow by symmetry, so no value is a difference of nearly equal numbers.
!>    beta = -inf is the box, beta = +inf the spike (a = 1 only at the lobe centre,
!>    v = d = 0); beta > 700 uses e^(-x)-scaled phi_k and cannot overflow.
!> 2. Classic pulses (amplitude A, time scale T), documented at `pulse_t`.
!>
!> The SI entry point is `pulse_t` + `pulse_eval` (m/s^2, m/s, m, s).
module seispulse_pulses
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_format, only: real_str
    use seispulse_optval, only: optval
    use seispulse_special, only: expm1, log1p, exp_phis, exp_phis_scaled, sin_pi, cos_pi, &
                                 tau_minus_sinpi, pi
    use seispulse_roots, only: scalar_function, find_root
    implicit none
    private

    ! dimensionless exponential pulse
    public :: exp_pulse, exp_pulse_point, exp_pulse_peaks, exp_pulse_impulse_amplitude
    ! the same, unchecked, with the beta constants computed once (for solvers)
    public :: exp_consts_t, exp_consts, exp_eval, check_beta, exp_rise_time
    ! SI pulses of every kind
    public :: pulse_t, pulse_validate, pulse_eval, pulse_at, pulse_breaks, pulse_end_time
    public :: pulse_kind_from_name, pulse_kind_name
    public :: exponential_pulse, half_sine_pulse, sine_cycle_pulse, cosine_cycle_pulse, &
              rectangular_pulse, triangular_pulse, ricker_pulse, mp_pulse
    public :: pulse_from_params, PULSE_NPARAM, PULSE_PARAM_AMP, PULSE_PARAM_DURATION, &
              PULSE_PARAM_BETA, PULSE_PARAM_FULL, PULSE_PARAM_PEAK_FRAC, PULSE_PARAM_FREQ, &
              PULSE_PARAM_T0, PULSE_PARAM_GAMMA, PULSE_PARAM_NU_DEG, PULSE_PARAM_CYCLES, &
              PULSE_MAX_CYCLES
    ! acceleration only (inner loops), peak acceleration, and the formulas solvers share
    public :: pulse_accel, pulse_peak_accel
    public :: ricker_accel, ricker_window, ricker_x_cut
    public :: mp_terms, mp_jerk_t, mp_jerk_of, mp_jerk, mp_jerk_slope
    public :: PULSE_EXPONENTIAL, PULSE_HALF_SINE, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, &
              PULSE_RECTANGULAR, PULSE_TRIANGULAR, PULSE_RICKER, PULSE_MP, PULSE_NKINDS

    integer, parameter :: PULSE_EXPONENTIAL = 1   !! Jacobsen & Ayre exponential pulse
    integer, parameter :: PULSE_HALF_SINE = 2     !! a = A sin(pi t/T), 0 <= t < T
    integer, parameter :: PULSE_SINE_CYCLE = 3    !! a = A sin(2 pi t/T), 0 <= t < n T
    integer, parameter :: PULSE_COSINE_CYCLE = 4  !! a = A cos(2 pi t/T), 0 <= t < n T
    integer, parameter :: PULSE_RECTANGULAR = 5   !! a = A, 0 <= t < T
    integer, parameter :: PULSE_TRIANGULAR = 6    !! rises to A at t = r T, back to 0 at T
    integer, parameter :: PULSE_RICKER = 7        !! Ricker wavelet (acceleration)
    integer, parameter :: PULSE_MP = 8            !! Mavroeidis & Papageorgiou (velocity)
    integer, parameter :: PULSE_NKINDS = 8

    !> Length of the packed parameter vector of `pulse_from_params` (the f2py layer).
    integer, parameter :: PULSE_NPARAM = 10
    !> Positions in that vector, by name (the Python layer packs by these names).
    integer, parameter :: PULSE_PARAM_AMP = 1, PULSE_PARAM_DURATION = 2, PULSE_PARAM_BETA = 3, &
                          PULSE_PARAM_FULL = 4, PULSE_PARAM_PEAK_FRAC = 5, PULSE_PARAM_FREQ = 6, &
                          PULSE_PARAM_T0 = 7, PULSE_PARAM_GAMMA = 8, PULSE_PARAM_NU_DEG = 9, &
                          PULSE_PARAM_CYCLES = 10
    !> Largest number of cycles of a sine or cosine cycle pulse.
    real(dp), parameter :: PULSE_MAX_CYCLES = 1.0e6_dp

    character(len=*), parameter :: kind_names(PULSE_NKINDS) = [character(len=24) :: &
        'exponential', 'half_sine', 'sine_cycle', 'cosine_cycle', 'rectangular', &
        'triangular', 'ricker', 'mavroeidis_papageorgiou']

    !> Above this beta the phi functions are used in e^(-x)-scaled form.
    real(dp), parameter :: beta_scaled = 700.0_dp

    real(dp), parameter :: two_pi = 2.0_dp * pi

    !> Ricker wavelet, the one underflow rule of every evaluation: where
    !> w = pi^2 f_p^2 (t - t0)^2 >= ricker_w_max the acceleration is +0 exactly. Not a
    !> truncation: e^(-w) rounds to 0 for w > 745.14 (below half the least subnormal,
    !> 2^-1075), so the formula (1 - 2 w) e^(-w) is already zero there; the branch only
    !> keeps the zero positive and avoids (1 - 2 w) * e^(-w) = -inf * 0 = NaN when w
    !> overflows to +inf.
    real(dp), parameter :: ricker_w_max = 750.0_dp
    !> Ricker wavelet: the support used by the piecewise solvers (seispulse_pieces,
    !> seispulse_sdof_closed), |x| = pi f_p |t - t0| <= ricker_x_cut; outside,
    !> |a| < 199 e^(-100) a_p < 1e-40 a_p and the solvers take a_g = 0 (see ricker_window).
    real(dp), parameter :: ricker_x_cut = 10.0_dp
    !> M&P peak search: at most this many scan steps over the window.
    integer, parameter :: mp_max_scan = 2**20

    !> Jerk of the Mavroeidis & Papageorgiou pulse in x = f_p (t - t0), in units of
    !> A f_p^2 (m/s^3 per m/s Hz^2): see `mp_jerk`. A scalar_function for find_root.
    type, extends(scalar_function) :: mp_jerk_t
        real(dp) :: k(3) = 0.0_dp   !! wave numbers of `mp_terms`
        real(dp) :: nu = 0.0_dp     !! phase (rad)
    contains
        procedure :: eval => mp_jerk_eval
    end type mp_jerk_t

    !> A pulse in SI units. Components not used by a kind are ignored.
    !>
    !> | kind | amp | time scale | others |
    !> |---|---|---|---|
    !> | exponential | A_g, peak acceleration (m/s^2) | duration = t_d, one lobe (s) | beta, full |
    !> | half_sine | peak acceleration | duration = pulse length | |
    !> | sine_cycle, cosine_cycle | peak acceleration | duration = period T_p | cycles n |
    !> | rectangular | acceleration | duration | |
    !> | triangular | peak acceleration | duration | peak_frac r in [0, 1] |
    !> | ricker | peak acceleration a_p at t0 | freq f_p (Hz) | t0 >= 0 (s) |
    !> | mavroeidis_papageorgiou | velocity amplitude A (m/s) | freq f_p (Hz) | gamma > 1, nu_deg,
    !> t0 |
    !>
    !> Sine and cosine cycles: n = `cycles` whole periods (1 <= n <= 10^6, default 1), so the
    !> pulse lasts n T_p: a = A sin(2 pi t/T_p) or A cos(2 pi t/T_p) on 0 <= t < n T_p
    !> (doc/pulses.md (P.11), (P.12)).
    !>
    !> Ricker: a = a_p (1 - 2 pi^2 f_p^2 (t - t0)^2) exp(-pi^2 f_p^2 (t - t0)^2) for t >= 0
    !> (f_p is the frequency of the Fourier amplitude peak; omega_p = 2 pi f_p gives
    !> Makris' form (1 - omega_p^2 t^2/2) exp(-omega_p^2 t^2/4)); zero before t = 0.
    !> Mavroeidis & Papageorgiou (2003, Eq. 1): v = (A/2)(1 + cos(2 pi f_p (t - t0)/gamma))
    !> cos(2 pi f_p (t - t0) + nu) for |t - t0| <= gamma/(2 f_p), zero outside; a is its
    !> derivative, d its integral from the start of the window; t0 >= gamma/(2 f_p)
    !> so that the pulse starts at t >= 0.
    type :: pulse_t
        integer :: kind = PULSE_EXPONENTIAL  !! one of the PULSE_* codes
        real(dp) :: amp = 1.0_dp             !! amplitude (m/s^2; m/s for M&P)
        real(dp) :: duration = 1.0_dp        !! t_d, pulse length or period (s)
        real(dp) :: beta = 0.0_dp            !! exponential shape parameter (-inf..+inf)
        logical :: full = .false.            !! exponential: full cycle (two lobes)
        real(dp) :: peak_frac = 0.5_dp       !! triangular: time of the peak / duration
        real(dp) :: freq = 1.0_dp            !! Ricker, M&P: f_p (Hz)
        real(dp) :: t0 = 1.5_dp              !! Ricker, M&P: centre time (s)
        real(dp) :: gamma = 2.0_dp           !! M&P: oscillatory character, > 1
        real(dp) :: nu_deg = 0.0_dp          !! M&P: phase (degrees)
        real(dp) :: cycles = 1.0_dp          !! sine, cosine cycle: number of periods n, whole
    end type pulse_t

    !> Constants of the exponential pulse that depend on beta only.
    type :: exp_consts_t
        integer :: form = 0         !! 0 direct, 1 scaled, 2 box (-inf), 3 spike (+inf)
        real(dp) :: beta = 0.0_dp
        real(dp) :: inv_p1 = 1.0_dp !! 1/phi_1(beta) (scaled form: 1/(e^-beta phi_1(beta)))
        real(dp) :: vg = 0.5_dp     !! V_g/(A_g t_d)
    end type exp_consts_t

    integer, parameter :: FORM_DIRECT = 0, FORM_SCALED = 1, FORM_BOX = 2, FORM_SPIKE = 3

contains

    ! ------------------------------------------------------------------------------
    ! Exponential pulse, dimensionless
    ! ------------------------------------------------------------------------------

    !> Acceleration, velocity and displacement of the exponential pulse at tau = t/t_d
    !> (half cycle on [0, 1], full cycle on [0, 2]); checked array form.
    !> `beta` has the length of `tau` or length 1.
    !> full is optional (default .false., as Python's `pulse.exp_pulse`); when omitted,
    !> pass a, v, d and stat by keyword.
    subroutine exp_pulse(tau, beta, full, a, v, d, stat, errmsg)
        real(dp), intent(in) :: tau(:)                        !! t/t_d, finite
        real(dp), intent(in) :: beta(:)                       !! shape, size 1 or size(tau); not NaN
        !> full cycle (two lobes); default .false.
        logical, intent(in), optional :: full
        real(dp), intent(out) :: a(:)                         !! acceleration / A_g
        real(dp), intent(out) :: v(:)                         !! velocity / (A_g t_d)
        real(dp), intent(out) :: d(:)                         !! displacement / (A_g t_d^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        integer :: i, n
        logical :: full_in
        full_in = optval(full, .false.)
        n = size(tau)
        if (size(beta) /= 1 .and. size(beta) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'beta: must have one value or one per tau')
            return
        end if
        if (size(a) /= n .or. size(v) /= n .or. size(d) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a, v, d: must have the length of tau')
            return
        end if
        call check_times(tau, 'tau', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, size(beta)
            call check_beta(beta(i), stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
        if (size(beta) == 1) then
            c = exp_consts(beta(1))
            do i = 1, n
                call exp_eval(c, tau(i), full_in, a(i), v(i), d(i))
            end do
        else
            do i = 1, n
                call exp_eval(exp_consts(beta(i)), tau(i), full_in, a(i), v(i), d(i))
            end do
        end if
    end subroutine exp_pulse

    !> Exponential pulse at one point, unchecked (tau finite, beta not NaN).
    elemental subroutine exp_pulse_point(tau, beta, full, a, v, d)
        real(dp), intent(in) :: tau    !! t/t_d
        real(dp), intent(in) :: beta   !! shape parameter, -inf..+inf
        logical, intent(in) :: full    !! full cycle (two lobes)
        real(dp), intent(out) :: a     !! acceleration / A_g
        real(dp), intent(out) :: v     !! velocity / (A_g t_d)
        real(dp), intent(out) :: d     !! displacement / (A_g t_d^2)
        call exp_eval(exp_consts(beta), tau, full, a, v, d)
    end subroutine exp_pulse_point

    !> Peak ground velocity and displacement of the exponential pulse (Table 1.3):
    !> vg = V_g/(A_g t_d) = 1/(1 - e^beta) + 1/beta, reached at t_d;
    !> dg = D_g/(A_g t_d^2) = vg/2 for a half cycle (the displacement at t_d; it grows
    !> without bound afterwards) and vg for a full cycle (reached at 2 t_d and kept).
    !> full is optional (default .false., as Python's `pulse.exp_pulse_peaks`); when
    !> omitted, pass vg, dg and stat by keyword.
    subroutine exp_pulse_peaks(beta, full, vg, dg, stat, errmsg)
        real(dp), intent(in) :: beta                          !! shape parameter (-), not NaN
        !> full cycle; default .false.
        logical, intent(in), optional :: full
        real(dp), intent(out) :: vg                           !! V_g/(A_g t_d)
        real(dp), intent(out) :: dg                           !! D_g/(A_g t_d^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        logical :: full_in
        full_in = optval(full, .false.)
        vg = 0.0_dp
        dg = 0.0_dp
        call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        c = exp_consts(beta)
        vg = c%vg
        if (full_in) then
            dg = vg
        else
            dg = 0.5_dp * vg
        end if
    end subroutine exp_pulse_peaks

    !> Unit-impulse normalization (doc/pulses.md section 1, unit impulse): the amplitude, in
    !> units of I/t_d, of the pulse whose lobe has area (impulse) I; equals 1/vg and
    !> is +inf for the spike, where a/vg tends to a Dirac delta at t_d/2.
    subroutine exp_pulse_impulse_amplitude(beta, amp, stat, errmsg)
        real(dp), intent(in) :: beta                          !! shape parameter (-), not NaN
        real(dp), intent(out) :: amp                          !! A_g t_d / I
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        amp = 0.0_dp
        call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        c = exp_consts(beta)
        if (c%form == FORM_SPIKE) then
            amp = ieee_value(amp, ieee_positive_inf)
        else
            amp = 1.0_dp / c%vg
        end if
    end subroutine exp_pulse_impulse_amplitude

    !> Time tau = t/t_d at which the rising branch of the exponential pulse reaches `level`
    !> (a fraction of A_g, 0 < level < 1): tau = ln(1 + level expm1(beta))/(2 beta), the
    !> onset of sliding (doc/sliding.md Eq. 1.12) and of rocking (Eq. 2.4); exact limits
    !> level/2 (beta = 0), 0 (-inf) and 1/2 (+inf). Unchecked.
    elemental function exp_rise_time(level, beta) result(tau)
        real(dp), intent(in) :: level  !! a/A_g in (0, 1)
        real(dp), intent(in) :: beta   !! pulse shape (-), not NaN
        real(dp) :: tau
        if (beta < -huge(beta)) then
            tau = 0.0_dp
        else if (beta > huge(beta)) then
            tau = 0.5_dp
        else if (beta > beta_scaled) then
            ! e^beta overflows: ln(1 + l (e^beta - 1)) = beta + ln(l + (1 - l) e^-beta)
            tau = 0.5_dp + log(level + (1.0_dp - level) * exp(-beta)) / (2.0_dp * beta)
        else if (abs(beta) > 0.0_dp) then
            tau = log1p(level * expm1(beta)) / (2.0_dp * beta)
        else
            tau = 0.5_dp * level
        end if
    end function exp_rise_time

    !> The beta-dependent constants, computed once per beta.
    elemental function exp_consts(beta) result(c)
        real(dp), intent(in) :: beta  !! shape parameter (-), not NaN
        type(exp_consts_t) :: c
        real(dp) :: p1, p2, p3
        c%beta = beta
        if (beta < -huge(beta)) then
            c%form = FORM_BOX
            c%vg = 1.0_dp
        else if (beta > huge(beta)) then
            c%form = FORM_SPIKE
            c%vg = 0.0_dp
        else if (beta > beta_scaled) then
            c%form = FORM_SCALED
            call exp_phis_scaled(beta, p1, p2, p3)
            c%inv_p1 = 1.0_dp / p1
            c%vg = p2 / p1
        else
            c%form = FORM_DIRECT
            call exp_phis(beta, p1, p2, p3)
            c%inv_p1 = 1.0_dp / p1
            c%vg = p2 / p1
        end if
    end function exp_consts

    !> Evaluate the half or full cycle at tau (doc/pulses.md section 1 in the phi_k form).
    !> One routine, not one per phase: this is the hot loop of every pulse table.
    elemental subroutine exp_eval(c, tau, full, a, v, d)
        type(exp_consts_t), intent(in) :: c  !! exp_consts(beta)
        real(dp), intent(in) :: tau          !! t/t_d (dimensionless), finite
        logical, intent(in) :: full          !! full cycle (two lobes)
        real(dp), intent(out) :: a           !! acceleration / A_g
        real(dp), intent(out) :: v           !! velocity / (A_g t_d)
        real(dp), intent(out) :: d           !! displacement / (A_g t_d^2)
        real(dp) :: s, r, x, p1, p2, p3, w
        logical :: second_lobe, falling
        if (tau < 0.0_dp) then
            a = 0.0_dp
            v = 0.0_dp
            d = 0.0_dp
            return
        else if (c%form == FORM_BOX) then
            call box_eval(tau, full, a, v, d)
            return
        else if (tau >= 1.0_dp .and. .not. full) then
            ! after a half cycle the ground keeps the velocity V_g
            a = 0.0_dp
            v = c%vg
            d = c%vg * (tau - 0.5_dp)
            return
        else if (tau >= 2.0_dp) then
            a = 0.0_dp
            v = 0.0_dp
            d = c%vg
            return
        end if
        ! negative lobe: a(tau) = -a(2 - tau), v(tau) = v(2 - tau), d(tau) = V_g - d(2 - tau),
        ! exact because the full cycle is odd about tau = 1
        second_lobe = tau > 1.0_dp
        s = tau
        if (second_lobe) s = 2.0_dp - tau
        if (c%form == FORM_SPIKE) then
            ! the limit beta -> +inf: a = 1 at the centre only, no area
            a = 0.0_dp
            if (.not. (abs(s - 0.5_dp) > 0.0_dp)) a = 1.0_dp
            v = 0.0_dp
            d = 0.0_dp
        else
            ! rising half r = s <= 1/2, or the falling half mirrored about s = 1/2
            falling = s > 0.5_dp
            r = s
            if (falling) r = 1.0_dp - s
            x = 2.0_dp * c%beta * r
            if (c%form == FORM_DIRECT) then
                call exp_phis(x, p1, p2, p3)
                w = 2.0_dp * r * c%inv_p1
            else
                ! phi_k(x)/phi_1(beta) = e^(x - beta) q_k(x)/q_1(beta), x - beta <= 0
                call exp_phis_scaled(x, p1, p2, p3)
                w = 2.0_dp * r * c%inv_p1 * exp(c%beta * (2.0_dp * r - 1.0_dp))
            end if
            a = w * p1
            v = w * r * p2
            d = w * r * r * p3
            if (falling) then
                v = c%vg - v
                d = c%vg * (s - 0.5_dp) + d
            end if
        end if
        if (second_lobe) then
            a = -a
            d = c%vg - d
        end if
    end subroutine exp_eval

    !> Box (beta = -inf, and the rectangular pulse): a = 1 on [0, 1), -1 on [1, 2).
    elemental subroutine box_eval(tau, full, a, v, d)
        real(dp), intent(in) :: tau
        logical, intent(in) :: full
        real(dp), intent(out) :: a, v, d
        real(dp) :: s
        if (tau < 0.0_dp) then
            a = 0.0_dp
            v = 0.0_dp
            d = 0.0_dp
        else if (tau < 1.0_dp) then
            a = 1.0_dp
            v = tau
            d = 0.5_dp * tau * tau
        else if (.not. full) then
            a = 0.0_dp
            v = 1.0_dp
            d = tau - 0.5_dp
        else if (tau < 2.0_dp) then
            s = 2.0_dp - tau
            a = -1.0_dp
            v = s
            d = 1.0_dp - 0.5_dp * s * s
        else
            a = 0.0_dp
            v = 0.0_dp
            d = 1.0_dp
        end if
    end subroutine box_eval

    ! ------------------------------------------------------------------------------
    ! Classic pulses, dimensionless (tau = t/T, a in A, v in A T, d in A T^2).
    ! Reached through pulse_point only, so tau >= 0 (rest before t = 0 is handled there).
    ! ------------------------------------------------------------------------------

    !> a = sin(pi tau) on [0, 1): v = (1 - cos pi tau)/pi, d = (tau - sin(pi tau)/pi)/pi.
    elemental subroutine half_sine_eval(tau, a, v, d)
        real(dp), intent(in) :: tau
        real(dp), intent(out) :: a, v, d
        if (tau < 1.0_dp) then
            a = sin_pi(tau)
            v = 2.0_dp * sin_pi(0.5_dp * tau)**2 / pi
            d = tau_minus_sinpi(tau) / pi
        else
            a = 0.0_dp
            v = 2.0_dp / pi
            d = (1.0_dp + 2.0_dp * (tau - 1.0_dp)) / pi
        end if
    end subroutine half_sine_eval

    !> n cycles a = sin(2 pi tau) on [0, n) (doc/pulses.md (P.11)): v = sin^2(pi tau)/pi
    !> (periodic, zero at every cycle end), d = (2 tau - sin(2 pi tau)/pi)/(4 pi) (growing by
    !> 1/(2 pi) per cycle); afterwards v = 0, d = n/(2 pi). n = 1 is the single cycle.
    elemental subroutine sine_cycle_eval(tau, n, a, v, d)
        real(dp), intent(in) :: tau
        real(dp), intent(in) :: n   !! number of cycles, whole, >= 1
        real(dp), intent(out) :: a, v, d
        if (tau < n) then
            a = sin_pi(2.0_dp * tau)
            v = sin_pi(tau)**2 / pi
            d = tau_minus_sinpi(2.0_dp * tau) / (4.0_dp * pi)
        else
            a = 0.0_dp
            v = 0.0_dp
            d = n * (0.5_dp / pi)
        end if
    end subroutine sine_cycle_eval

    !> n cycles a = cos(2 pi tau) on [0, n) (doc/pulses.md (P.12)): v = sin(2 pi tau)/(2 pi),
    !> d = sin^2(pi tau)/(2 pi^2), both periodic; velocity and displacement return to zero
    !> at every cycle end and stay zero after tau = n.
    elemental subroutine cosine_cycle_eval(tau, n, a, v, d)
        real(dp), intent(in) :: tau
        real(dp), intent(in) :: n   !! number of cycles, whole, >= 1
        real(dp), intent(out) :: a, v, d
        if (tau >= n) then
            a = 0.0_dp
            v = 0.0_dp
            d = 0.0_dp
        else
            a = cos_pi(2.0_dp * tau)
            v = sin_pi(2.0_dp * tau) / (2.0_dp * pi)
            d = sin_pi(tau)**2 / (2.0_dp * pi * pi)
        end if
    end subroutine cosine_cycle_eval

    !> Triangle rising linearly to 1 at tau = r and back to 0 at tau = 1 (r = 0: decaying
    !> from a jump; r = 1: rising to a jump). Written in q = tau - r on the falling side
    !> so that no term cancels.
    elemental subroutine triangular_eval(tau, r, a, v, d)
        real(dp), intent(in) :: tau, r
        real(dp), intent(out) :: a, v, d
        real(dp) :: q, rr
        if (tau < r) then
            a = tau / r
            v = 0.5_dp * tau * tau / r
            d = tau**3 / (6.0_dp * r)
        else if (tau < 1.0_dp) then
            q = tau - r
            rr = 1.0_dp - r
            a = 1.0_dp - q / rr
            v = 0.5_dp * r + q - 0.5_dp * q * q / rr
            d = r * r / 6.0_dp + 0.5_dp * r * q + 0.5_dp * q * q - q**3 / (6.0_dp * rr)
        else
            a = 0.0_dp
            v = 0.5_dp
            d = (2.0_dp - r) / 6.0_dp + 0.5_dp * (tau - 1.0_dp)
        end if
    end subroutine triangular_eval

    !> Ricker wavelet in tau = f_p t, centre tau0 = f_p t0, truncated at tau = 0:
    !> a = (1 - 2 w) e^(-w), w = pi^2 (tau - tau0)^2; v in A/f_p, d in A/f_p^2.
    elemental subroutine ricker_eval(tau, tau0, a, v, d)
        real(dp), intent(in) :: tau, tau0
        real(dp), intent(out) :: a, v, d
        real(dp) :: x, w, e0, z
        x = tau - tau0
        w = pi * pi * x * x
        e0 = exp(-pi * pi * tau0 * tau0)
        if (w < ricker_w_max) then
            a = (1.0_dp - 2.0_dp * w) * exp(-w)
            ! v = [x e^(-pi^2 x^2)] from -tau0 to x
            v = x * exp(-w) + tau0 * e0
        else
            ! e^(-w) underflows: the wavelet is over (and w may be +inf: no inf * 0)
            a = 0.0_dp
            v = tau0 * e0
        end if
        ! d = (e0 - e^(-w))/(2 pi^2) + tau0 e0 tau, with w - pi^2 tau0^2 = pi^2 tau (tau - 2 tau0)
        z = pi * pi * tau * (tau - 2.0_dp * tau0)
        if (abs(z) < 1.0_dp) then
            d = -e0 * expm1(-z) / (2.0_dp * pi * pi)
        else
            d = (e0 - exp(-w)) / (2.0_dp * pi * pi)
        end if
        d = d + tau0 * e0 * tau
    end subroutine ricker_eval

    !> Mavroeidis & Papageorgiou velocity pulse in tau = f_p t (tau0 = f_p t0):
    !> v in A, a in A f_p, d in A/f_p.
    elemental subroutine mp_eval(tau, tau0, gamma, nu, a, v, d)
        real(dp), intent(in) :: tau, tau0, gamma, nu
        real(dp), intent(out) :: a, v, d
        real(dp) :: x, x0, xe, env, denv, c, s
        x0 = -0.5_dp * gamma
        x = tau - tau0
        if (x < x0) then
            a = 0.0_dp
            v = 0.0_dp
            d = 0.0_dp
            return
        end if
        xe = min(x, -x0)
        ! d = int_{x0}^{xe} v; v = cos(2 pi x + nu)/2 + [cos(k+ x + nu) + cos(k- x + nu)]/4
        d = 0.5_dp * cos_integral(2.0_dp * pi, nu, x0, xe) &
            + 0.25_dp * cos_integral(2.0_dp * pi * (1.0_dp + 1.0_dp / gamma), nu, x0, xe) &
            + 0.25_dp * cos_integral(2.0_dp * pi * (1.0_dp - 1.0_dp / gamma), nu, x0, xe)
        if (x > -x0) then
            a = 0.0_dp
            v = 0.0_dp
            return
        end if
        env = 1.0_dp + cos_pi(2.0_dp * x / gamma)
        denv = -2.0_dp * pi / gamma * sin_pi(2.0_dp * x / gamma)
        c = cos(2.0_dp * pi * x + nu)
        s = sin(2.0_dp * pi * x + nu)
        v = 0.5_dp * env * c
        a = 0.5_dp * (denv * c - 2.0_dp * pi * env * s)
    end subroutine mp_eval

    !> int_{x0}^{x1} cos(k y + nu) dy = 2 cos(k (x0 + x1)/2 + nu) sin(k (x1 - x0)/2)/k,
    !> with the k -> 0 limit (x1 - x0) cos(nu) (no division by a small k).
    elemental function cos_integral(k, nu, x0, x1) result(y)
        real(dp), intent(in) :: k, nu, x0, x1
        real(dp) :: y
        real(dp) :: h
        h = 0.5_dp * k * (x1 - x0)
        if (abs(h) < 1.0e-8_dp) then
            y = (x1 - x0) * (1.0_dp - h * h / 6.0_dp) * cos(0.5_dp * k * (x0 + x1) + nu)
        else
            y = 2.0_dp * cos(0.5_dp * k * (x0 + x1) + nu) * sin(h) / k
        end if
    end function cos_integral

    ! ------------------------------------------------------------------------------
    ! Acceleration only, peak acceleration, and the pieces of formulas that solvers
    ! share (Ricker support, M&P wave numbers and jerk)
    ! ------------------------------------------------------------------------------

    !> Acceleration (m/s^2) of a valid pulse at time t (s), without v and d: the inner loop
    !> of the integrators (seispulse_rocking_sim). Inside the pulse, the sine and cosine
    !> cycles, the half sine and the rectangle take one transcendental call,
    !> sin(2 pi t/T) etc. (pulse_at reduces the argument exactly with sin_pi: the two
    !> agree to a few ulps of the argument, which grows with the number of cycles: about
    !> 7e-13 relative at n = 1000; not bitwise), and the Ricker wavelet is `ricker_accel`; every
    !> other case, and t < 0 or t >= the end of the pulse (rest), is pulse_at's value.
    !> `consts` as in pulse_at.
    elemental function pulse_accel(p, t, consts) result(a)
        type(pulse_t), intent(in) :: p                          !! a valid pulse
        real(dp), intent(in) :: t                               !! time (s)
        !> exp_consts(p%beta), to skip recomputing it; absent: computed
        type(exp_consts_t), intent(in), optional :: consts
        real(dp) :: a                                           !! a_g(t) (m/s^2)
        real(dp) :: v, d, te
        select case (p%kind)
        case (PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, PULSE_HALF_SINE, PULSE_RECTANGULAR)
            te = p%duration
            if (p%kind == PULSE_SINE_CYCLE .or. p%kind == PULSE_COSINE_CYCLE) &
                te = p%duration * p%cycles
            if (t >= 0.0_dp .and. t < te) then
                select case (p%kind)
                case (PULSE_SINE_CYCLE)
                    a = p%amp * sin(two_pi * (t / p%duration))
                case (PULSE_COSINE_CYCLE)
                    a = p%amp * cos(two_pi * (t / p%duration))
                case (PULSE_HALF_SINE)
                    a = p%amp * sin(pi * (t / p%duration))
                case default
                    a = p%amp
                end select
                return
            end if
        case (PULSE_RICKER)
            if (t >= 0.0_dp) then
                a = ricker_accel(p, t)
                return
            end if
        end select
        if (present(consts)) then
            call pulse_at(p, t, a, v, d, consts)
        else
            call pulse_at(p, t, a, v, d)
        end if
    end function pulse_accel

    !> Ricker acceleration a = a_p (1 - 2 x^2) e^(-x^2), x = pi f_p (t - t0) (m/s^2), the
    !> wavelet continued to t < 0 (pulse_at and pulse_accel give 0 there). +0 where
    !> x^2 >= ricker_w_max (e^(-x^2) underflows: see ricker_w_max). Agrees with pulse_at,
    !> which forms x from f_p t - f_p t0, to a few ulps (not bitwise).
    elemental function ricker_accel(p, t) result(a)
        type(pulse_t), intent(in) :: p   !! a Ricker pulse (amp, freq, t0 used)
        real(dp), intent(in) :: t        !! time (s)
        real(dp) :: a                    !! acceleration (m/s^2)
        real(dp) :: w
        w = (pi * p%freq * (t - p%t0))**2
        if (w < ricker_w_max) then
            a = p%amp * (1.0_dp - 2.0_dp * w) * exp(-w)
        else
            a = 0.0_dp
        end if
    end function ricker_accel

    !> Support [ts, te] (s) of the Ricker wavelet for the piecewise solvers:
    !> |pi f_p (t - t0)| <= ricker_x_cut, starting no earlier than t = 0.
    pure subroutine ricker_window(p, ts, te)
        type(pulse_t), intent(in) :: p   !! a valid Ricker pulse
        real(dp), intent(out) :: ts      !! max(0, t0 - ricker_x_cut/(pi f_p)) (s)
        real(dp), intent(out) :: te      !! t0 + ricker_x_cut/(pi f_p) (s)
        ts = max(0.0_dp, p%t0 - ricker_x_cut / (pi * p%freq))
        te = p%t0 + ricker_x_cut / (pi * p%freq)
    end subroutine ricker_window

    !> Wave numbers k (in x = f_p (t - t0), rad) and weights w of the M&P velocity in
    !> product-to-sum form, v = A sum_j w_j cos(k_j x + nu) on the window:
    !> k = 2 pi (1, 1 + 1/gamma, 1 - 1/gamma), w = (1/2, 1/4, 1/4); so
    !> a = -A f_p sum w_j k_j sin(k_j x + nu) and the jerk -A f_p^2 sum w_j k_j^2 cos(...).
    pure subroutine mp_terms(gamma, k, w)
        real(dp), intent(in) :: gamma   !! oscillatory character, > 1
        real(dp), intent(out) :: k(3)   !! wave numbers (rad per unit x)
        real(dp), intent(out) :: w(3)   !! weights
        k = two_pi * [1.0_dp, 1.0_dp + 1.0_dp / gamma, 1.0_dp - 1.0_dp / gamma]
        w = [0.5_dp, 0.25_dp, 0.25_dp]
    end subroutine mp_terms

    !> The jerk function of a valid M&P pulse (wave numbers of mp_terms, nu in radians).
    pure function mp_jerk_of(p) result(f)
        type(pulse_t), intent(in) :: p   !! a valid M&P pulse
        type(mp_jerk_t) :: f
        real(dp) :: w(3)
        call mp_terms(p%gamma, f%k, w)
        f%nu = p%nu_deg * (pi / 180.0_dp)
    end function mp_jerk_of

    !> M&P jerk in units of A f_p^2 at x = f_p (t - t0) inside the window (d^2 v/dx^2 / A):
    !> -[k1^2 cos(k1 x + nu) + (k2^2 cos(k2 x + nu) + k3^2 cos(k3 x + nu))/2]/2.
    pure function mp_jerk(f, x) result(y)
        type(mp_jerk_t), intent(in) :: f   !! wave numbers and phase
        real(dp), intent(in) :: x          !! f_p (t - t0)
        real(dp) :: y
        y = -0.5_dp * (f%k(1)**2 * cos(f%k(1) * x + f%nu) &
                       + 0.5_dp * (f%k(2)**2 * cos(f%k(2) * x + f%nu) &
                                   + f%k(3)**2 * cos(f%k(3) * x + f%nu)))
    end function mp_jerk

    !> d/dx of mp_jerk (units A f_p^2 per unit x).
    pure function mp_jerk_slope(f, x) result(y)
        type(mp_jerk_t), intent(in) :: f   !! wave numbers and phase
        real(dp), intent(in) :: x          !! f_p (t - t0)
        real(dp) :: y
        y = 0.5_dp * (f%k(1)**3 * sin(f%k(1) * x + f%nu) &
                      + 0.5_dp * (f%k(2)**3 * sin(f%k(2) * x + f%nu) &
                                  + f%k(3)**3 * sin(f%k(3) * x + f%nu)))
    end function mp_jerk_slope

    !> mp_jerk as a `scalar_function` for the root finder (units A f_p per unit x).
    function mp_jerk_eval(self, x) result(y)
        class(mp_jerk_t), intent(inout) :: self  !! wave numbers and phase
        real(dp), intent(in) :: x                !! f_p (t - t0) (dimensionless)
        real(dp) :: y
        y = mp_jerk(self, x)
    end function mp_jerk_eval

    !> Peak |a_g| (m/s^2) of the pulse and its time (s): |amp| at the peak of each kind;
    !> Mavroeidis & Papageorgiou by a scan (step 1/(64 f_p)) and Brent on the closed-form jerk.
    !> The spike (beta = +inf) reports |amp| at t_d/2 although it has no area.
    subroutine pulse_peak_accel(p, a_max, t_max, stat, errmsg)
        type(pulse_t), intent(in) :: p                        !! the pulse (SI)
        real(dp), intent(out) :: a_max                        !! max |a_g| (m/s^2)
        real(dp), intent(out) :: t_max                        !! its time (s)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        a_max = 0.0_dp
        t_max = 0.0_dp
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        a_max = abs(p%amp)
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            if (p%beta < -huge(1.0_dp)) then
                t_max = 0.0_dp
            else
                t_max = 0.5_dp * p%duration
            end if
        case (PULSE_HALF_SINE)
            t_max = 0.5_dp * p%duration
        case (PULSE_SINE_CYCLE)
            t_max = 0.25_dp * p%duration
        case (PULSE_TRIANGULAR)
            t_max = p%peak_frac * p%duration
        case (PULSE_RICKER)
            t_max = p%t0
        case (PULSE_MP)
            call mp_peak_accel(p, a_max, t_max)
        case default
            t_max = 0.0_dp
        end select
    end subroutine pulse_peak_accel

    !> a/(A f_p) of the M&P pulse at x inside the window (mp_terms' k, w).
    pure function mp_accel(k, w, nu, x) result(a)
        real(dp), intent(in) :: k(3), w(3), nu, x
        real(dp) :: a
        a = -sum(w * k * sin(k * x + nu))
    end function mp_accel

    !> Bound of |a|/(A f_p) of the M&P pulse at |x|: a = (A f_p/2)[env' cos(phi)
    !> - 2 pi env sin(phi)], env = 1 + cos(2 pi x/gamma), so |a|/(A f_p) <= pi sqrt(
    !> sin^2(u)/gamma^2 + (1 + cos u)^2), u = 2 pi x/gamma, decreasing in |x| for gamma >= 1.
    pure function mp_bound(gam, x) result(b)
        real(dp), intent(in) :: gam, x
        real(dp) :: b
        b = pi * hypot(sin_pi(2.0_dp * x / gam) / gam, 1.0_dp + cos_pi(2.0_dp * x / gam))
    end function mp_bound

    !> Peak |a_g| of the M&P pulse: a scan (step 1/64 in x) with Brent on the closed-form jerk,
    !> first over |x| <= 4 (the envelope's peak is at x = 0), widened (doubling) until the
    !> bound mp_bound at the window's edge is below the best value found, so that nothing
    !> outside can be larger; at most the whole window |x| <= gamma/2. The work does not
    !> grow with gamma for large gamma (the integer count cannot overflow).
    subroutine mp_peak_accel(p, a_max, t_max)
        type(pulse_t), intent(in) :: p
        real(dp), intent(out) :: a_max, t_max
        type(mp_jerk_t) :: f
        real(dp) :: xw, x0, x1, xa, xb, ja, jb, best, xbest, xr, val, w(3)
        integer :: n, j, stat
        f = mp_jerk_of(p)
        call mp_terms(p%gamma, f%k, w)
        best = -1.0_dp
        xbest = 0.0_dp
        xw = min(0.5_dp * p%gamma, 4.0_dp)
        do
            x0 = -xw
            x1 = xw
            n = int(min(real(mp_max_scan, dp), max(64.0_dp, 128.0_dp * xw)))
            xa = x0
            ja = f%eval(xa)
            do j = 0, n
                xb = x0 + (x1 - x0) * real(j, dp) / real(n, dp)
                jb = f%eval(xb)
                val = abs(mp_accel(f%k, w, f%nu, xb))
                if (val > best) then
                    best = val
                    xbest = xb
                end if
                if (j > 0 .and. ((ja > 0.0_dp .and. jb < 0.0_dp) .or. &
                                 (ja < 0.0_dp .and. jb > 0.0_dp))) then
                    call find_root(f, xa, xb, xr, stat, fa_known=ja, fb_known=jb)
                    if (stat == SEISPULSE_SUCCESS) then
                        val = abs(mp_accel(f%k, w, f%nu, xr))
                        if (val > best) then
                            best = val
                            xbest = xr
                        end if
                    end if
                end if
                xa = xb
                ja = jb
            end do
            if (xw >= 0.5_dp * p%gamma) exit
            if (mp_bound(p%gamma, xw) <= best) exit
            xw = min(0.5_dp * p%gamma, 2.0_dp * xw)
        end do
        a_max = abs(p%amp) * p%freq * best
        t_max = p%t0 + xbest / p%freq
    end subroutine mp_peak_accel

    ! ------------------------------------------------------------------------------
    ! SI pulses
    ! ------------------------------------------------------------------------------

    !> Exponential pulse: A_g (m/s^2), t_d (s), beta, full cycle or not.
    pure function exponential_pulse(amp, td, beta, full) result(p)
        real(dp), intent(in) :: amp   !! A_g, peak acceleration (m/s^2)
        real(dp), intent(in) :: td    !! t_d, duration of one lobe (s)
        real(dp), intent(in) :: beta  !! shape parameter
        !> full cycle; default .false.
        logical, intent(in), optional :: full
        type(pulse_t) :: p
        logical :: full_in
        full_in = optval(full, .false.)
        p = timed_pulse(PULSE_EXPONENTIAL, amp, td)
        p%beta = beta
        p%full = full_in
    end function exponential_pulse

    !> Half-sine acceleration pulse a = A sin(pi t/T) on [0, T).
    pure function half_sine_pulse(amp, duration) result(p)
        real(dp), intent(in) :: amp       !! peak acceleration (m/s^2)
        real(dp), intent(in) :: duration  !! pulse length T (s)
        type(pulse_t) :: p
        p = timed_pulse(PULSE_HALF_SINE, amp, duration)
    end function half_sine_pulse

    !> Sine acceleration pulse of n cycles, a = A sin(2 pi t/T_p) on [0, n T_p).
    pure function sine_cycle_pulse(amp, period, cycles) result(p)
        real(dp), intent(in) :: amp     !! peak acceleration (m/s^2)
        real(dp), intent(in) :: period  !! T_p (s)
        integer, intent(in), optional :: cycles  !! n, 1 <= n <= 10^6 (default 1)
        type(pulse_t) :: p
        p = timed_pulse(PULSE_SINE_CYCLE, amp, period)
        if (present(cycles)) p%cycles = real(cycles, dp)
    end function sine_cycle_pulse

    !> Cosine acceleration pulse of n cycles, a = A cos(2 pi t/T_p) on [0, n T_p).
    pure function cosine_cycle_pulse(amp, period, cycles) result(p)
        real(dp), intent(in) :: amp     !! peak acceleration (m/s^2)
        real(dp), intent(in) :: period  !! T_p (s)
        integer, intent(in), optional :: cycles  !! n, 1 <= n <= 10^6 (default 1)
        type(pulse_t) :: p
        p = timed_pulse(PULSE_COSINE_CYCLE, amp, period)
        if (present(cycles)) p%cycles = real(cycles, dp)
    end function cosine_cycle_pulse

    !> Rectangular acceleration pulse a = A on [0, T).
    pure function rectangular_pulse(amp, duration) result(p)
        real(dp), intent(in) :: amp       !! acceleration (m/s^2)
        real(dp), intent(in) :: duration  !! T (s)
        type(pulse_t) :: p
        p = timed_pulse(PULSE_RECTANGULAR, amp, duration)
    end function rectangular_pulse

    !> Triangular acceleration pulse: 0 at t = 0, A at t = r T, 0 at t = T.
    pure function triangular_pulse(amp, duration, peak_frac) result(p)
        real(dp), intent(in) :: amp        !! peak acceleration (m/s^2)
        real(dp), intent(in) :: duration   !! T (s)
        !> r in [0, 1]; default 0.5
        real(dp), intent(in), optional :: peak_frac
        type(pulse_t) :: p
        real(dp) :: frac_in
        frac_in = optval(peak_frac, 0.5_dp)
        p = timed_pulse(PULSE_TRIANGULAR, amp, duration)
        p%peak_frac = frac_in
    end function triangular_pulse

    !> A pulse described by its kind, amplitude and duration only.
    pure function timed_pulse(kind, amp, duration) result(p)
        integer, intent(in) :: kind
        real(dp), intent(in) :: amp, duration
        type(pulse_t) :: p
        p%kind = kind
        p%amp = amp
        p%duration = duration
    end function timed_pulse

    !> Ricker wavelet of peak acceleration a_p at t0 and dominant frequency f_p.
    pure function ricker_pulse(amp, freq, t0) result(p)
        real(dp), intent(in) :: amp   !! a_p (m/s^2)
        real(dp), intent(in) :: freq  !! f_p (Hz)
        real(dp), intent(in) :: t0    !! centre (s), >= 0
        type(pulse_t) :: p
        p%kind = PULSE_RICKER
        p%amp = amp
        p%freq = freq
        p%t0 = t0
    end function ricker_pulse

    !> Mavroeidis & Papageorgiou (2003) velocity pulse.
    pure function mp_pulse(vamp, freq, gamma, nu_deg, t0) result(p)
        real(dp), intent(in) :: vamp    !! A, velocity amplitude (m/s)
        real(dp), intent(in) :: freq    !! f_p, prevailing frequency (Hz)
        real(dp), intent(in) :: gamma   !! oscillatory character, > 1
        real(dp), intent(in) :: nu_deg  !! phase nu (degrees)
        real(dp), intent(in) :: t0      !! envelope peak (s), >= gamma/(2 f_p)
        type(pulse_t) :: p
        p%kind = PULSE_MP
        p%amp = vamp
        p%freq = freq
        p%gamma = gamma
        p%nu_deg = nu_deg
        p%t0 = t0
    end function mp_pulse

    !> Build a pulse from its kind and a packed vector (used by the f2py layer), each
    !> parameter at its position PULSE_PARAM_<name> (full: 0 or 1).
    pure function pulse_from_params(kind, params) result(p)
        integer, intent(in) :: kind                  !! PULSE_* code
        real(dp), intent(in) :: params(PULSE_NPARAM) !! packed parameters
        type(pulse_t) :: p
        p%kind = kind
        p%amp = params(PULSE_PARAM_AMP)
        p%duration = params(PULSE_PARAM_DURATION)
        p%beta = params(PULSE_PARAM_BETA)
        p%full = params(PULSE_PARAM_FULL) > 0.5_dp
        p%peak_frac = params(PULSE_PARAM_PEAK_FRAC)
        p%freq = params(PULSE_PARAM_FREQ)
        p%t0 = params(PULSE_PARAM_T0)
        p%gamma = params(PULSE_PARAM_GAMMA)
        p%nu_deg = params(PULSE_PARAM_NU_DEG)
        p%cycles = params(PULSE_PARAM_CYCLES)
    end function pulse_from_params

    !> Check a pulse; the message names the offending parameter and its range.
    subroutine pulse_validate(p, stat, errmsg)
        type(pulse_t), intent(in) :: p                       !! the pulse
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (p%kind < 1 .or. p%kind > PULSE_NKINDS) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'kind: unknown pulse kind (allowed: '//kind_list()//')')
            return
        end if
        if (.not. ieee_is_finite(p%amp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'amp = '//real_str(p%amp) &
                           //': must be a finite number (a negative amplitude reverses the pulse)')
            return
        end if
        select case (p%kind)
        case (PULSE_RICKER, PULSE_MP)
            if (.not. (ieee_is_finite(p%freq) .and. p%freq > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'freq = ' &
                               //real_str(p%freq)//': must be a finite number > 0 (Hz)')
                return
            end if
            if (.not. (ieee_is_finite(p%t0) .and. p%t0 >= 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't0 = ' &
                               //real_str(p%t0)//': must be a finite number >= 0 (s)')
                return
            end if
        case default
            if (.not. (ieee_is_finite(p%duration) .and. p%duration > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'duration = ' &
                               //real_str(p%duration)//': must be a finite number > 0 (s)')
                return
            end if
        end select
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            call check_beta(p%beta, stat, errmsg)
        case (PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE)
            call check_cycles(p%cycles, stat, errmsg)
            ! the end of the pulse, T n, must be a number (a valid T alone may not do);
            ! compared by a division, which cannot overflow (n >= 1); nested: Fortran does
            ! not short-circuit, and a NaN n must not reach the division (-ffpe-trap)
            if (stat == SEISPULSE_SUCCESS) then
                if (p%duration > huge(1.0_dp) / p%cycles) &
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'cycles = ' &
                                   //real_str(p%cycles)//': the pulse would end at period x ' &
                                   //'cycles = '//real_str(p%duration)//' x ' &
                                   //real_str(p%cycles)//' s, beyond the largest number')
            end if
        case (PULSE_TRIANGULAR)
            if (ieee_is_nan(p%peak_frac) .or. p%peak_frac < 0.0_dp &
                .or. p%peak_frac > 1.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'peak_frac = ' &
                               //real_str(p%peak_frac)//': must be in [0, 1]')
            end if
        case (PULSE_MP)
            if (.not. (ieee_is_finite(p%gamma) .and. p%gamma > 1.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = ' &
                               //real_str(p%gamma)//': must be a finite number > 1')
            else if (.not. ieee_is_finite(p%nu_deg)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'nu_deg = ' &
                               //real_str(p%nu_deg)//': must be a finite number (degrees)')
            else if (p%freq * p%t0 < 0.5_dp * p%gamma * (1.0_dp - 1.0e-9_dp)) then
                ! the window [t0 - gamma/(2 f_p), t0 + gamma/(2 f_p)] must start at t >= 0
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't0 = ' &
                               //real_str(p%t0)//': must be >= gamma/(2 freq) = ' &
                               //real_str(0.5_dp * p%gamma / p%freq) &
                               //' s, so that the pulse starts at t >= 0')
            end if
        end select
    end subroutine pulse_validate

    !> Acceleration (m/s^2), velocity (m/s) and displacement (m) at times t (s);
    !> checked array form.
    subroutine pulse_eval(p, t, a, v, d, stat, errmsg)
        type(pulse_t), intent(in) :: p                        !! the pulse
        real(dp), intent(in) :: t(:)                          !! times (s), finite
        real(dp), intent(out) :: a(:)                         !! acceleration (m/s^2)
        real(dp), intent(out) :: v(:)                         !! velocity (m/s)
        real(dp), intent(out) :: d(:)                         !! displacement (m)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        real(dp) :: t_end
        integer :: i
        if (size(a) /= size(t) .or. size(v) /= size(t) .or. size(d) /= size(t)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a, v, d: must have the length of t')
            return
        end if
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_times(t, 't', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (p%kind == PULSE_EXPONENTIAL) c = exp_consts(p%beta)   ! once for the array
        t_end = pulse_end_time(p)
        do i = 1, size(t)
            call pulse_point(p, c, t_end, t(i), a(i), v(i), d(i))
        end do
    end subroutine pulse_eval

    !> Pulse at time t (s), unchecked: for integrators that have validated `p` once.
    !> Without `consts` each call recomputes the beta constants of an exponential pulse
    !> (two exp calls); an integrator passes `exp_consts(p%beta)` computed once.
    elemental subroutine pulse_at(p, t, a, v, d, consts)
        type(pulse_t), intent(in) :: p                          !! a valid pulse
        real(dp), intent(in) :: t                               !! time (s)
        real(dp), intent(out) :: a                              !! acceleration (m/s^2)
        real(dp), intent(out) :: v                              !! velocity (m/s)
        real(dp), intent(out) :: d                              !! displacement (m)
        !> exp_consts(p%beta), to skip recomputing it; absent: computed
        type(exp_consts_t), intent(in), optional :: consts
        type(exp_consts_t) :: c
        if (present(consts)) then
            call pulse_point(p, consts, pulse_end_time(p), t, a, v, d)
        else
            if (p%kind == PULSE_EXPONENTIAL) c = exp_consts(p%beta)
            call pulse_point(p, c, pulse_end_time(p), t, a, v, d)
        end if
    end subroutine pulse_at

    !> One point in SI. Before t = 0 the ground is at rest (tested on t itself: a tiny
    !> t/T rounds to -0). After the end of the pulse the ground moves at the constant
    !> velocity it ended with, d = d_end + v_end (t - t_end), so t/T never has to be
    !> formed beyond ~2 and no time scale can overflow it.
    elemental subroutine pulse_point(p, c, t_end, t, a, v, d)
        type(pulse_t), intent(in) :: p
        type(exp_consts_t), intent(in) :: c   !! exponential constants (other kinds: unused)
        real(dp), intent(in) :: t_end         !! pulse_end_time(p)
        real(dp), intent(in) :: t
        real(dp), intent(out) :: a, v, d
        if (t < 0.0_dp) then
            a = 0.0_dp
            v = 0.0_dp
            d = 0.0_dp
        else if (t > t_end) then
            call pulse_core(p, c, t_end, a, v, d)
            a = 0.0_dp
            d = d + v * (t - t_end)
        else
            call pulse_core(p, c, t, a, v, d)
        end if
    end subroutine pulse_point

    !> The closed forms of each kind, scaled to SI.
    elemental subroutine pulse_core(p, c, t, a, v, d)
        type(pulse_t), intent(in) :: p
        type(exp_consts_t), intent(in) :: c
        real(dp), intent(in) :: t
        real(dp), intent(out) :: a, v, d
        real(dp) :: tau
        select case (p%kind)
        case (PULSE_RICKER)
            call ricker_eval(p%freq * t, p%freq * p%t0, a, v, d)
        case (PULSE_MP)
            call mp_eval(p%freq * t, p%freq * p%t0, p%gamma, p%nu_deg * (pi / 180.0_dp), a, v, d)
        case default
            tau = t / p%duration
            select case (p%kind)
            case (PULSE_EXPONENTIAL)
                call exp_eval(c, tau, p%full, a, v, d)
            case (PULSE_HALF_SINE)
                call half_sine_eval(tau, a, v, d)
            case (PULSE_SINE_CYCLE)
                call sine_cycle_eval(cycle_tau(p, t, tau), p%cycles, a, v, d)
            case (PULSE_COSINE_CYCLE)
                call cosine_cycle_eval(cycle_tau(p, t, tau), p%cycles, a, v, d)
            case (PULSE_RECTANGULAR)
                call box_eval(tau, .false., a, v, d)
            case (PULSE_TRIANGULAR)
                call triangular_eval(tau, p%peak_frac, a, v, d)
            case default
                a = 0.0_dp
                v = 0.0_dp
                d = 0.0_dp
            end select
        end select
        call scale_to_si(p, a, v, d)
    end subroutine pulse_core

    !> tau = t/T of the n-cycle pulses with the end decided in time, as pulse_end_time does
    !> (t_end = T n): t/T may round to n just below t_end, or below n at t_end itself.
    elemental function cycle_tau(p, t, tau_raw) result(tau)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: t, tau_raw
        real(dp) :: tau
        if (t >= p%duration * p%cycles) then
            tau = p%cycles
        else
            tau = min(tau_raw, nearest(p%cycles, -1.0_dp))
        end if
    end function cycle_tau

    !> From the dimensionless core to SI: a in A, v in A T, d in A T^2 (T the time scale;
    !> M&P: v in A, a in A f_p, d in A/f_p).
    elemental subroutine scale_to_si(p, a, v, d)
        type(pulse_t), intent(in) :: p
        real(dp), intent(inout) :: a, v, d
        real(dp) :: ts
        select case (p%kind)
        case (PULSE_MP)
            a = p%amp * p%freq * a
            v = p%amp * v
            d = p%amp / p%freq * d
        case default
            if (p%kind == PULSE_RICKER) then
                ts = 1.0_dp / p%freq
            else
                ts = p%duration
            end if
            ! scale the dimensionless value first: amp * ts * ts alone can over- or
            ! underflow for extreme time scales while the product is representable
            a = p%amp * a
            v = p%amp * (ts * v)
            d = p%amp * (ts * (ts * d))
        end select
    end subroutine scale_to_si

    !> Times (s) where the acceleration has a kink or a jump, ascending: an integrator
    !> steps exactly onto them. The last one is where the pulse ends (none for Ricker;
    !> n T for n sine or cosine cycles).
    pure subroutine pulse_breaks(p, breaks, nbreaks)
        type(pulse_t), intent(in) :: p   !! a valid pulse
        real(dp), intent(out) :: breaks(5) !! break times (s), first nbreaks valid
        integer, intent(out) :: nbreaks  !! number of break times
        real(dp) :: half
        breaks = 0.0_dp
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            if (p%full) then
                nbreaks = 5
                breaks = p%duration * [0.0_dp, 0.5_dp, 1.0_dp, 1.5_dp, 2.0_dp]
            else
                nbreaks = 3
                breaks(1:3) = p%duration * [0.0_dp, 0.5_dp, 1.0_dp]
            end if
        case (PULSE_TRIANGULAR)
            nbreaks = 3
            breaks(1:3) = p%duration * [0.0_dp, p%peak_frac, 1.0_dp]
        case (PULSE_RICKER)
            nbreaks = 1
        case (PULSE_MP)
            nbreaks = 2
            half = 0.5_dp * p%gamma / p%freq
            breaks(1:2) = [p%t0 - half, p%t0 + half]
        case (PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE)
            ! smooth across the cycle ends: the jumps and kinks are at 0 and n T only
            nbreaks = 2
            breaks(2) = p%duration * p%cycles
        case default
            nbreaks = 2
            breaks(2) = p%duration
        end select
    end subroutine pulse_breaks

    !> Time (s) after which the acceleration is zero for good; +inf for the Ricker wavelet.
    pure function pulse_end_time(p) result(t_end)
        type(pulse_t), intent(in) :: p  !! a valid pulse
        real(dp) :: t_end
        real(dp) :: breaks(5)
        integer :: nbreaks
        if (p%kind == PULSE_RICKER) then
            t_end = ieee_value(t_end, ieee_positive_inf)
        else
            call pulse_breaks(p, breaks, nbreaks)
            t_end = breaks(nbreaks)
        end if
    end function pulse_end_time

    !> Kind code from a name (case-insensitive; aliases exp, sine, cosine, rect,
    !> triangle, mp).
    subroutine pulse_kind_from_name(name, kind, stat, errmsg)
        character(len=*), intent(in) :: name                  !! pulse name
        integer, intent(out) :: kind                          !! PULSE_* code
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        character(len=len(name)) :: low
        integer :: i, ic
        low = adjustl(name)
        do i = 1, len(low)
            ic = iachar(low(i:i))
            if (ic >= iachar('A') .and. ic <= iachar('Z')) low(i:i) = achar(ic + 32)
        end do
        stat = SEISPULSE_SUCCESS
        select case (trim(low))
        case ('exp')
            kind = PULSE_EXPONENTIAL
        case ('sine')
            kind = PULSE_SINE_CYCLE
        case ('cosine')
            kind = PULSE_COSINE_CYCLE
        case ('rect')
            kind = PULSE_RECTANGULAR
        case ('triangle')
            kind = PULSE_TRIANGULAR
        case ('mp')
            kind = PULSE_MP
        case default
            kind = findloc(kind_names, trim(low), dim=1)
            if (kind == 0) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                'kind = '''//trim(name)//''': unknown pulse (allowed: '//kind_list()//')')
        end select
    end subroutine pulse_kind_from_name

    !> Canonical name of a kind code ('unknown' for a bad code).
    pure function pulse_kind_name(kind) result(name)
        integer, intent(in) :: kind  !! PULSE_* code
        character(len=len_trim(pulse_kind_name_text(kind))) :: name
        name = pulse_kind_name_text(kind)
    end function pulse_kind_name

    !> pulse_kind_name(kind) padded with blanks.
    pure function pulse_kind_name_text(kind) result(name)
        integer, intent(in) :: kind
        character(len=64) :: name
        if (kind >= 1 .and. kind <= PULSE_NKINDS) then
            name = trim(kind_names(kind))
        else
            name = 'unknown'
        end if
    end function pulse_kind_name_text

    pure function kind_list() result(list)
        character(len=len_trim(kind_list_text())) :: list
        list = kind_list_text()
    end function kind_list

    !> kind_list() padded with blanks.
    pure function kind_list_text() result(list)
        character(len=PULSE_NKINDS * (len(kind_names) + 2)) :: list
        integer :: i
        list = kind_names(1)
        do i = 2, PULSE_NKINDS
            list = trim(list)//', '//trim(kind_names(i))
        end do
    end function kind_list_text

    !> Number of cycles of a sine or cosine cycle pulse: a whole number 1 <= n <= 10^6.
    subroutine check_cycles(cycles, stat, errmsg)
        real(dp), intent(in) :: cycles                        !! number of cycles
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        ! NaN first (no ordered comparison with NaN: it traps under -ffpe-trap=invalid)
        if (ieee_is_nan(cycles)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'cycles = ' &
                           //real_str(cycles)//': must be a whole number in [1, 1000000]')
        else if (cycles < 1.0_dp .or. cycles > PULSE_MAX_CYCLES) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'cycles = ' &
                           //real_str(cycles)//': must be a whole number in [1, 1000000]')
        else if (abs(aint(cycles) - cycles) > 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'cycles = ' &
                           //real_str(cycles)//': must be a whole number in [1, 1000000]')
        end if
    end subroutine check_cycles

    !> beta of the exponential pulse: any real number or +-inf, not NaN.
    subroutine check_beta(beta, stat, errmsg)
        real(dp), intent(in) :: beta                          !! pulse shape
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (ieee_is_nan(beta)) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
            'beta = NaN: must be a real number or +-inf (-inf box, 0 triangle, +inf spike)')
    end subroutine check_beta

    subroutine check_times(t, name, stat, errmsg)
        real(dp), intent(in) :: t(:)
        character(len=*), intent(in) :: name
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: i
        stat = SEISPULSE_SUCCESS
        do i = 1, size(t)
            if (.not. ieee_is_finite(t(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//' = ' &
                               //real_str(t(i))//': must be a finite number')
                return
            end if
        end do
    end subroutine check_times

end module seispulse_pulses
