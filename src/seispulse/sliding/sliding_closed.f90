!> Rigid block sliding on a frictional plane under the exponential pulse of
!> Jacobsen & Ayre: the closed forms of chapter 1 of Ref. [GR], corrected and in stable
!> form (theory and corrections: doc/sliding.md; equation numbers below are the
!> chapter's, sections are those of doc/sliding.md).
!>
!> Dimensionless throughout: tau = t/t_d, eta = a_y/A_g (a_y = mu g on a horizontal
!> plane), velocities in A_g t_d, displacements in A_g t_d^2; the pulse is Eq. 1.1b
!> (half cycle) or 1.2a (full cycle), the convention of everything but Eq. 1.1a (doc/pulses.md
!> Corrections 1).
!>
!> Every slide is computed the same way: the onset from the explicit inverse of the
!> rising branch (1.12, 1.34); the stop either in free sliding after the lobe (1.7,
!> which is 1.23 for a late start) or as the root of the relative velocity inside the
!> lobe (1.8, corrected 1.19, and the forced reverse stop of section 7) on a proven
!> bracket; the displacement by Eq. 1.5 with the ground velocity and displacement of
!> seispulse_pulses, never through the printed expansions 1.9/1.14/1.18/1.24, which
!> cancel catastrophically for beta < 0 and small eta (section 3) and, for 1.24, are
!> wrong (doc/sliding.md Corrections 5). Eq. 1.5 itself carries an absolute error of a few ulps of
!> the ground displacement over the slide: as eta -> 1 the slip (~ (1 - eta)^3) keeps that
!> absolute, not a relative, accuracy (a Taylor-remainder form would be needed there).
module seispulse_sliding_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: outside
    use seispulse_optval, only: optval
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_format, only: real_str
    use seispulse_special, only: expm1, log1p, pi
    use seispulse_roots, only: scalar_function, find_root, smooth_function, find_root_newton
    use seispulse_pulses, only: exp_consts_t, exp_consts, exp_eval, exponential_pulse, &
                                check_beta, exp_rise_time
    use seispulse_sliding_sim, only: friction_t, stickslip_result_t, stickslip_pulse
    implicit none
    private

    public :: half_cycle_t, full_cycle_t, sliding_block_t
    public :: yield_time, half_cycle, full_cycle, inclined_resistances, block_response, &
              block_response_eta
    public :: half_cycle_integrated, full_cycle_integrated, summarize_slides
    public :: eta_critical, eta_critical_regression, full_cycle_peak_regression
    public :: rectangle_half, rectangle_full, triangle_half, spike_velocity_ratio
    public :: sliding_regime_name, sliding_mode_name
    public :: SLIDING_REGIME_NONE, SLIDING_REGIME_FORCED, SLIDING_REGIME_FREE
    public :: SLIDING_MODE_NO_SLIDING, SLIDING_MODE_UNILATERAL, SLIDING_MODE_STICK, &
              SLIDING_MODE_SLIP, SLIDING_MODE_STUCK, SLIDING_MODE_REVERSE_ONLY

    integer, parameter :: SLIDING_REGIME_NONE = 0    !! no sliding (eta >= 1)
    integer, parameter :: SLIDING_REGIME_FORCED = 1  !! the slide stops during the pulse, tau_m <= 1
    integer, parameter :: SLIDING_REGIME_FREE = 2    !! the slide stops after the pulse, tau_m > 1

    integer, parameter :: SLIDING_MODE_NO_SLIDING = 0    !! neither lobe starts a slide
    integer, parameter :: SLIDING_MODE_UNILATERAL = 1    !! forward slide only: eta2 >= 1
    integer, parameter :: SLIDING_MODE_STICK = 2         !! sticks, then slides back (1.21a)
    integer, parameter :: SLIDING_MODE_SLIP = 3          !! it slides back at once (1.21b)
    integer, parameter :: SLIDING_MODE_STUCK = 4         !! eta2 < 1, but the forward slide outlasts
                                                 !! the reverse window (section 7)
    integer, parameter :: SLIDING_MODE_REVERSE_ONLY = 5  !! eta1 >= 1 > eta2: the second lobe only

    character(len=*), parameter :: regime_names(0:2) = [character(len=6) :: &
        'none', 'forced', 'free']
    character(len=*), parameter :: mode_names(0:5) = [character(len=12) :: &
        'no_sliding', 'unilateral', 'stick', 'slip', 'stuck', 'reverse_only']

    !> Half-cycle response (section 3), dimensionless.
    type :: half_cycle_t
        real(dp) :: tau_y = 0.0_dp         !! onset t_y/t_d (NaN without sliding)
        real(dp) :: tau_m = 0.0_dp         !! stop = time of the peak slip t_m/t_d (NaN without)
        integer :: regime = SLIDING_REGIME_NONE    !! SLIDING_REGIME_*
        real(dp) :: um = 0.0_dp            !! peak (= residual) slip u_m/(A_g t_d^2)
        real(dp) :: dugm = 0.0_dp          !! ground displacement during the slide / (A_g t_d^2)
        real(dp) :: vm = 0.0_dp            !! peak sliding velocity V_m/V_g
    end type half_cycle_t

    !> Full-cycle response (sections 4, 5, 7), dimensionless; times from the pulse start.
    type :: full_cycle_t
        integer :: mode = SLIDING_MODE_NO_SLIDING  !! SLIDING_MODE_*
        real(dp) :: tau_y1 = 0.0_dp        !! forward onset (NaN without a forward slide)
        real(dp) :: tau_m1 = 0.0_dp        !! forward stop = time of the peak slip
        real(dp) :: um1 = 0.0_dp           !! forward (peak) slip / (A_g t_d^2), >= 0
        real(dp) :: tau_y2 = 0.0_dp        !! reverse onset (NaN without a reverse slide)
        real(dp) :: tau_m2 = 0.0_dp        !! reverse stop
        real(dp) :: um2 = 0.0_dp           !! reverse slip / (A_g t_d^2), >= 0
        real(dp) :: ures = 0.0_dp          !! residual um1 - um2 (negative: net reverse slip)
        real(dp) :: vm1 = 0.0_dp           !! peak forward sliding velocity / V_g
        real(dp) :: vm2 = 0.0_dp           !! peak reverse sliding velocity / V_g
    end type full_cycle_t

    !> A block on an incline hit by a pulse, in SI (section 7): along-plane slips.
    type :: sliding_block_t
        integer :: mode = SLIDING_MODE_NO_SLIDING  !! SLIDING_MODE_* (no sliding or unilateral)
        real(dp) :: eta1 = 0.0_dp          !! resistance to downhill sliding / A_g
        real(dp) :: eta2 = 0.0_dp          !! resistance to uphill sliding / A_g
        real(dp) :: t_y1 = 0.0_dp          !! downhill onset (s from the pulse start)
        real(dp) :: t_m1 = 0.0_dp          !! downhill stop (s)
        real(dp) :: u_m1 = 0.0_dp          !! downhill slip (m), the peak displacement
        real(dp) :: t_y2 = 0.0_dp          !! uphill onset (s)
        real(dp) :: t_m2 = 0.0_dp          !! uphill stop (s)
        real(dp) :: u_m2 = 0.0_dp          !! uphill slip (m), >= 0
        real(dp) :: u_res = 0.0_dp         !! residual (m), downhill positive
        real(dp) :: v_m1 = 0.0_dp          !! peak downhill sliding velocity (m/s)
        real(dp) :: v_m2 = 0.0_dp          !! peak uphill sliding velocity (m/s)
    end type sliding_block_t

    !> Relative velocity of a forward slide from rest at tau0, the left side of Eq. 1.8
    !> (half cycle) or of the corrected Eq. 1.19 (full cycle), in the form of Eq. 1.4:
    !> w(tau) = v_g(tau) - v_g(tau0) - eta (tau - tau0).
    !> Its slope is the relative acceleration a_g(tau) - eta (for Newton's method).
    !> `late` (half cycle): w = rest0 - (V_g - v_g(tau)) - eta (tau - tau0), with rest0 =
    !> V_g - v_g(tau0) given, free of the cancellation of the first form near the lobe end.
    type, extends(smooth_function) :: slide_velocity
        type(exp_consts_t) :: c
        logical :: full = .false., late = .false.
        real(dp) :: tau0 = 0.0_dp, v0 = 0.0_dp, eta = 0.0_dp, rest0 = 0.0_dp
    contains
        procedure :: eval => slide_velocity_eval
        procedure :: eval_slope => slide_velocity_slope
    end type slide_velocity

    !> tau_m1(eta) - 1 - tau_y(eta): zero on the stick/slip boundary (section 5).
    type, extends(scalar_function) :: stick_slip_margin
        type(exp_consts_t) :: c
        integer :: stat = SEISPULSE_SUCCESS
    contains
        procedure :: eval => stick_slip_margin_eval
    end type stick_slip_margin

contains

    ! ------------------------------------------------------------------------------
    ! Onset
    ! ------------------------------------------------------------------------------

    !> Onset time tau_y = t_y/t_d of sliding under the exponential pulse (Eq. 1.12), and
    !> with static friction a*eta at the onset (Eq. 1.34). NaN when a*eta >= 1: no sliding.
    !> static_factor is optional (default 1, as Python's `sliding.yield_time`); when
    !> omitted, pass tau_y and stat by keyword.
    subroutine yield_time(eta, beta, static_factor, tau_y, stat, errmsg)
        real(dp), intent(in) :: eta                           !! a_y/A_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        !> a >= 1 (1: no static friction); default 1.0
        real(dp), intent(in), optional :: static_factor
        real(dp), intent(out) :: tau_y                        !! t_y/t_d in [0, 1/2], or NaN
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: static_in
        static_in = optval(static_factor, 1.0_dp)
        tau_y = ieee_value(tau_y, ieee_quiet_nan)
        call check_half(eta, beta, static_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (static_in * eta < 1.0_dp) tau_y = exp_rise_time(static_in * eta, beta)
    end subroutine yield_time

    ! ------------------------------------------------------------------------------
    ! One slide
    ! ------------------------------------------------------------------------------

    !> A slide in the positive sense from rest at tau0 under the lobe a(tau) of the pulse
    !> (the second lobe of a full cycle, mirrored, for a reverse slide; section 5), with
    !> kinetic resistance eta. The lobe must exceed eta at tau0 (the onset, or the instant of
    !> an immediate reversal). `full`: the ground carries on with the mirrored lobe (first
    !> slide of a full cycle, corrected Eq. 1.19), otherwise with the constant velocity V_g.
    !> rest0 (half cycle only): V_g - v_g(tau0), the ground velocity the lobe still gives,
    !> when the caller has it without the cancellation of that difference (a reversal late
    !> in the lobe, section 5); used when it is below V_g/1024.
    subroutine one_slide(c, full, tau0, eta, tau_m, um, dug, vm, regime, stat, errmsg, rest0)
        type(exp_consts_t), intent(in) :: c
        logical, intent(in) :: full
        real(dp), intent(in) :: tau0, eta
        real(dp), intent(out) :: tau_m, um, dug, vm
        integer, intent(out) :: regime, stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(in), optional :: rest0
        type(slide_velocity) :: w
        real(dp) :: a0, v0, d0, ty, tau_k, a, v, d, w_k, w_hi, hi, h, dv
        logical :: moves
        ! relative acceleration a - eta stays positive up to tau_k, where the falling
        ! branch comes down to eta (tau_k = 1 - tau_y(eta), section 3)
        ty = exp_rise_time(eta, c%beta)
        tau_k = 1.0_dp - ty
        call exp_eval(c, tau0, full, a0, v0, d0)
        stat = SEISPULSE_SUCCESS
        dv = c%vg - v0
        moves = tau_k > tau0
        if (present(rest0) .and. .not. full) then
            ! below V_g/1024 the difference V_g - v0 keeps fewer than about 43 of the 53 bits
            ! (none once rest0 is below the rounding of V_g: no bracket, or a wrong stop), and
            ! tau0 as little of its distance to the lobe end: then the lobe exceeds eta at
            ! tau0 if more ground velocity is left than after tau_k, v_g(tau_y(eta)) by
            ! symmetry. Above, the difference is good to about 2^-43, and kept (the results
            ! there are those of before)
            if (rest0 < c%vg / 1024.0_dp) then
                w%late = .true.
                w%rest0 = rest0
                dv = rest0
                call exp_eval(c, ty, .false., a, v, d)
                moves = rest0 > v
            end if
        end if
        if (.not. moves) then
            ! the lobe only touches eta: a slide of zero length (the spike, beta = +inf)
            tau_m = tau0
            um = 0.0_dp
            dug = 0.0_dp
            vm = 0.0_dp
            regime = SLIDING_REGIME_FORCED
            return
        end if
        w%c = c
        w%full = full
        w%tau0 = tau0
        w%v0 = v0
        w%eta = eta
        w_k = w%eval(tau_k)
        vm = w_k / c%vg
        ! Eq. 1.7 (1.23 for tau0 > 1/2): after the lobe the ground velocity is V_g and the
        ! block stops at tau0 + (V_g - v_g(tau0))/eta, if that is after the lobe
        ! (+-inf without the overflow, for an eta near the smallest double)
        if (eta >= 1.0_dp) then
            h = dv / eta
        else if (abs(dv) < eta * huge(1.0_dp)) then
            h = dv / eta
        else
            h = sign(ieee_value(h, ieee_positive_inf), dv)
        end if
        if (.not. full .and. tau0 + h > 1.0_dp) then
            regime = SLIDING_REGIME_FREE
            tau_m = tau0 + h
        else
            ! forced stop, Eq. 1.8 / corrected 1.19 / section 7: w > 0 at tau_k and falls
            ! monotonically to w < 0 at the upper end, so the root is unique (safeguarded
            ! Newton: the slope a_g - eta comes with the value)
            if (full) then
                ! v_g(2 - tau_y) = v_g(tau_y) <= v_g(tau0): w(2 - tau_y) < 0 (section 4)
                hi = 2.0_dp - ty
            else
                hi = 1.0_dp
            end if
            w_hi = w%eval(hi)
            if (w_hi < 0.0_dp .and. tau_k < hi) then
                call find_root_newton(w, tau_k, hi, tau_m, stat, errmsg, fa_known=w_k, &
                                      fb_known=w_hi)
                if (stat /= SEISPULSE_SUCCESS) return
            else
                ! on the free/forced boundary (tau_m = 1 up to rounding), or a bracket
                ! [1 - tau_y, 1] narrower than the rounding of 1 (tau_k = 1)
                tau_m = hi
            end if
            regime = SLIDING_REGIME_FORCED
            if (tau_m > 1.0_dp) regime = SLIDING_REGIME_FREE
        end if
        ! Eq. 1.5: u_m = u_g(tau_m) - u_g(tau0) - (tau_m - tau0) v_g(tau0)
        !                - eta (tau_m - tau0)^2/2
        call exp_eval(c, tau_m, full, a, v, d)
        h = tau_m - tau0
        dug = d - d0
        um = max((dug - h * v0) - 0.5_dp * eta * h * h, 0.0_dp)
    end subroutine one_slide

    function slide_velocity_eval(self, x) result(y)
        class(slide_velocity), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: dy
        call self%eval_slope(x, y, dy)
    end function slide_velocity_eval

    subroutine slide_velocity_slope(self, x, y, dy)
        class(slide_velocity), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: y, dy
        real(dp) :: a, v, d
        if (self%late) then
            ! the half-cycle lobe is symmetric: V_g - v_g(x) = v_g(1 - x), a_g(x) = a_g(1 - x)
            if (x >= 1.0_dp) then
                a = 0.0_dp
                v = 0.0_dp
            else if (x > 0.5_dp) then
                call exp_eval(self%c, 1.0_dp - x, .false., a, v, d)
            else
                call exp_eval(self%c, x, .false., a, v, d)
                v = self%c%vg - v
            end if
            y = (self%rest0 - v) - self%eta * (x - self%tau0)
        else
            call exp_eval(self%c, x, self%full, a, v, d)
            y = (v - self%v0) - self%eta * (x - self%tau0)
        end if
        dy = a - self%eta
    end subroutine slide_velocity_slope

    !> V_m/V_g of the spike limit (beta = +inf) with onset resistance eta_on and kinetic
    !> eta: [(1 - eta_on) + (1 - eta) + eta ln(eta_on eta)]/2; 1 - eta(1 - ln eta) for
    !> eta_on = eta (section 3).
    elemental function spike_vm(eta_on, eta) result(vm)
        real(dp), intent(in) :: eta_on, eta
        real(dp) :: vm
        ! two logarithms: eta_on eta underflows to 0 for a subnormal eta
        vm = 0.5_dp * ((1.0_dp - eta_on) + (1.0_dp - eta) + eta * (log(eta_on) + log(eta)))
    end function spike_vm

    ! ------------------------------------------------------------------------------
    ! Half cycle
    ! ------------------------------------------------------------------------------

    !> Response to a half-cycle pulse (section 3; static friction: section 8).
    !> Sliding needs static_factor*eta < 1; otherwise regime = SLIDING_REGIME_NONE with zero slip.
    !> static_factor is optional (default 1, as Python's `sliding.half_cycle`); when
    !> omitted, pass res and stat by keyword.
    subroutine half_cycle(eta, beta, static_factor, res, stat, errmsg)
        real(dp), intent(in) :: eta                           !! kinetic a_y/A_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        !> a >= 1: onset at a*eta; default 1.0
        real(dp), intent(in), optional :: static_factor
        type(half_cycle_t), intent(out) :: res                !! the response
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        real(dp) :: static_in
        static_in = optval(static_factor, 1.0_dp)
        call check_half(eta, beta, static_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        res%tau_y = ieee_value(res%tau_y, ieee_quiet_nan)
        res%tau_m = res%tau_y
        if (.not. (static_in * eta < 1.0_dp)) return
        c = exp_consts(beta)
        res%tau_y = exp_rise_time(static_in * eta, beta)
        call one_slide(c, .false., res%tau_y, eta, res%tau_m, res%um, res%dugm, res%vm, &
                       res%regime, stat, errmsg)
        if (beta > huge(beta)) res%vm = spike_vm(static_in * eta, eta)
    end subroutine half_cycle

    ! ------------------------------------------------------------------------------
    ! Full cycle
    ! ------------------------------------------------------------------------------

    !> Response to a full-cycle pulse: forward slide, then stick or slip and a reverse slide
    !> (Tables 1.1 and 1.4 with the corrected criterion of section 7 and the forced reverse
    !> stop of section 7). eta1 resists forward (downhill) sliding, eta2 reverse sliding.
    !> Static friction (section 8) acts at the first onset, and at the reverse onset too
    !> when static_reverse.
    !> static_factor and static_reverse are optional (defaults 1 and .false., as Python's
    !> `sliding.full_cycle`); when one is omitted, pass res and stat by keyword.
    subroutine full_cycle(eta1, eta2, beta, static_factor, static_reverse, res, stat, errmsg)
        real(dp), intent(in) :: eta1                          !! forward a_y1/A_g > 0
        real(dp), intent(in) :: eta2                          !! reverse a_y2/A_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        !> a >= 1; default 1.0
        real(dp), intent(in), optional :: static_factor
        !> a also at the reverse onset; default .false.
        logical, intent(in), optional :: static_reverse
        type(full_cycle_t), intent(out) :: res                !! the response
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: c
        real(dp) :: nan, on2, tbar0, tbar_m, dug, a1, v1, d1, v2, rest
        integer :: regime
        real(dp) :: static_in
        logical :: reverse_in
        static_in = optval(static_factor, 1.0_dp)
        reverse_in = optval(static_reverse, .false.)
        call check_full(eta1, eta2, beta, static_in, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        nan = ieee_value(nan, ieee_quiet_nan)
        res%tau_y1 = nan
        res%tau_m1 = nan
        res%tau_y2 = nan
        res%tau_m2 = nan
        c = exp_consts(beta)

        if (.not. (static_in * eta1 < 1.0_dp)) then
            ! no forward slide: the second lobe acts alone, as a half cycle (section 7)
            if (.not. (static_in * eta2 < 1.0_dp)) return
            res%mode = SLIDING_MODE_REVERSE_ONLY
            tbar0 = exp_rise_time(static_in * eta2, beta)
            call reverse_slide(static_in * eta2)
            return
        end if

        ! forward slide: onset 1.12/1.34, stop by the corrected 1.19 on [1 - tau_y, 2 - tau_y]
        res%tau_y1 = exp_rise_time(static_in * eta1, beta)
        call one_slide(c, .true., res%tau_y1, eta1, res%tau_m1, res%um1, dug, res%vm1, &
                       regime, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (beta > huge(beta)) res%vm1 = spike_vm(static_in * eta1, eta1)
        res%ures = res%um1
        res%mode = SLIDING_MODE_UNILATERAL
        on2 = eta2
        if (reverse_in) on2 = static_in * eta2
        if (.not. (on2 < 1.0_dp)) return

        ! the second lobe exceeds on2 on (1 + tau_y(on2), 2 - tau_y(on2)) (section 7)
        tbar0 = exp_rise_time(on2, beta)
        ! ground velocity at the forward stop by Eq. 1.6, v_g(tau_m1) = v_g(tau_y1) +
        ! eta1 (tau_m1 - tau_y1) (section 2): near tau = 2 it is O(eta1) and keeps its relative
        ! precision, where tau_m1 keeps only that of 2 (it is 2 to rounding for a tiny eta1)
        call exp_eval(c, res%tau_y1, .true., a1, v1, d1)
        rest = v1 + eta1 * (res%tau_m1 - res%tau_y1)
        call exp_eval(c, tbar0, .true., a1, v2, d1)
        if (res%tau_m1 <= 1.0_dp + tbar0) then
            res%mode = SLIDING_MODE_STICK
            call reverse_slide(on2)
        else if (rest > v2) then
            ! tau_m1 < 2 - tau_y(on2), in velocities: v_g(tau_m1) > v_g(2 - tau_y(on2)) =
            ! v_g(tau_y(on2)), as v_g falls monotonically to 0 at tau = 2
            res%mode = SLIDING_MODE_SLIP
            tbar0 = res%tau_m1 - 1.0_dp
            ! the mirrored lobe still gives V_g - v(tbar0) = v_g(tau_m1)
            call reverse_slide(on2, rest)
        else
            res%mode = SLIDING_MODE_STUCK
        end if

    contains

        !> The reverse slide is a forward slide on the mirrored second lobe in the shifted
        !> time tbar = tau - 1, with kinetic eta2 (Table 1.1 with the bars of Table 1.4).
        subroutine reverse_slide(eta_on, rest0)
            real(dp), intent(in) :: eta_on
            real(dp), intent(in), optional :: rest0  !! V_g - v(tbar0), see one_slide
            call one_slide(c, .false., tbar0, eta2, tbar_m, res%um2, dug, res%vm2, regime, &
                           stat, errmsg, rest0)
            if (stat /= SEISPULSE_SUCCESS) return
            if (beta > huge(beta)) res%vm2 = spike_vm(eta_on, eta2)
            res%tau_y2 = 1.0_dp + tbar0
            res%tau_m2 = 1.0_dp + tbar_m
            res%ures = res%um1 - res%um2
        end subroutine reverse_slide

    end subroutine full_cycle

    ! ------------------------------------------------------------------------------
    ! The same quantities from the event-driven integrator (the check of the above)
    ! ------------------------------------------------------------------------------

    !> `half_cycle` computed by the stick-slip integrator of seispulse_sliding_sim on the
    !> dimensionless pulse (A_g = 1, t_d = 1) instead of the closed forms.
    subroutine half_cycle_integrated(eta, beta, static_factor, res, stat, errmsg)
        real(dp), intent(in) :: eta                           !! kinetic a_y/A_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(in) :: static_factor                 !! a >= 1: onset at a*eta
        type(half_cycle_t), intent(out) :: res                !! the response
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(full_cycle_t) :: f
        real(dp) :: d0, d1
        call full_cycle_integrated(eta, eta, beta, static_factor, .false., .false., f, stat, &
                                   errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        res%tau_y = f%tau_y1
        res%tau_m = f%tau_m1
        res%um = f%um1
        res%vm = f%vm1
        res%regime = SLIDING_REGIME_NONE
        if (f%mode /= SLIDING_MODE_NO_SLIDING) then
            res%regime = SLIDING_REGIME_FORCED
            if (res%tau_m > 1.0_dp) res%regime = SLIDING_REGIME_FREE
            d0 = ground_displacement(res%tau_y)
            d1 = ground_displacement(res%tau_m)
            res%dugm = d1 - d0
        end if
    contains
        real(dp) function ground_displacement(tau)
            real(dp), intent(in) :: tau
            real(dp) :: a, v
            call exp_eval(exp_consts(beta), tau, .false., a, v, ground_displacement)
        end function ground_displacement
    end subroutine half_cycle_integrated

    !> `full_cycle` (or, with full = .false., the half cycle as a full_cycle_t) computed by
    !> the stick-slip integrator on the dimensionless pulse.
    subroutine full_cycle_integrated(eta1, eta2, beta, static_factor, static_reverse, full, &
                                     res, stat, errmsg)
        real(dp), intent(in) :: eta1                          !! forward a_y1/A_g > 0
        real(dp), intent(in) :: eta2                          !! reverse a_y2/A_g > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(in) :: static_factor                 !! a >= 1
        logical, intent(in) :: static_reverse                 !! a also at the reverse onset
        logical, intent(in) :: full                           !! full cycle
        type(full_cycle_t), intent(out) :: res                !! the response
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(stickslip_result_t) :: ss
        type(exp_consts_t) :: c
        real(dp) :: on2
        call check_full(eta1, eta2, beta, static_factor, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call stickslip_pulse(exponential_pulse(1.0_dp, 1.0_dp, beta, full), &
                             friction_t(ay_fwd=eta1, ay_rev=eta2, static_factor=static_factor, &
                                        static_all=static_reverse), ss, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        on2 = eta2
        if (static_reverse) on2 = static_factor * eta2
        call summarize_slides(ss, full .and. on2 < 1.0_dp, res)
        c = exp_consts(beta)
        if (c%vg > 0.0_dp) then
            res%vm1 = res%vm1 / c%vg
            res%vm2 = res%vm2 / c%vg
        end if
    end subroutine full_cycle_integrated

    !> The first forward and first reverse slide of an integrator run as a full_cycle_t, in
    !> the run's units (vm1, vm2: the peak sliding velocities themselves). Mode as in
    !> `full_cycle`: a single forward slide is 'stuck' when a reverse slide was possible
    !> (`reverse_possible`), else 'unilateral'.
    subroutine summarize_slides(ss, reverse_possible, res)
        type(stickslip_result_t), intent(in) :: ss  !! integrator result
        logical, intent(in) :: reverse_possible      !! the excitation could start a reverse slide
        type(full_cycle_t), intent(out) :: res       !! the summary
        integer :: i, ifwd, irev
        res%tau_y1 = ieee_value(res%tau_y1, ieee_quiet_nan)
        res%tau_m1 = res%tau_y1
        res%tau_y2 = res%tau_y1
        res%tau_m2 = res%tau_y1
        ifwd = 0
        irev = 0
        do i = size(ss%slides), 1, -1
            if (ss%slides(i)%direction > 0) ifwd = i
            if (ss%slides(i)%direction < 0) irev = i
        end do
        if (ifwd > 0) then
            associate (s => ss%slides(ifwd))
                res%tau_y1 = s%t_start
                res%tau_m1 = s%t_stop
                res%um1 = s%u_stop - s%u_start
                res%vm1 = s%w_peak
            end associate
        end if
        if (irev > 0) then
            associate (s => ss%slides(irev))
                res%tau_y2 = s%t_start
                res%tau_m2 = s%t_stop
                res%um2 = s%u_start - s%u_stop
                res%vm2 = s%w_peak
            end associate
        end if
        res%ures = ss%u_final
        if (ifwd == 0 .and. irev == 0) then
            res%mode = SLIDING_MODE_NO_SLIDING
        else if (ifwd == 0) then
            res%mode = SLIDING_MODE_REVERSE_ONLY
        else if (irev == 0) then
            res%mode = SLIDING_MODE_UNILATERAL
            if (reverse_possible) res%mode = SLIDING_MODE_STUCK
        else if (ss%slides(irev)%from_slip) then
            res%mode = SLIDING_MODE_SLIP
        else
            res%mode = SLIDING_MODE_STICK
        end if
    end subroutine summarize_slides

    ! ------------------------------------------------------------------------------
    ! Stick/slip boundary and the chapter's regressions
    ! ------------------------------------------------------------------------------

    !> The critical strength eta_cr(beta) of the symmetric full cycle: the block slips
    !> (reverses at once) for eta < eta_cr and sticks above (section 5), the root of
    !> tau_m1(eta) = 1 + tau_y(eta) in (0, 1). 1 for the rectangle, 0 for the spike.
    subroutine eta_critical(beta, eta_cr, stat, errmsg)
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        real(dp), intent(out) :: eta_cr                       !! critical eta
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(stick_slip_margin) :: f
        eta_cr = ieee_value(eta_cr, ieee_quiet_nan)
        call check_beta(beta, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (beta < -huge(beta)) then
            eta_cr = 1.0_dp   ! rectangle: tau_m1 = 2/(1 + eta) > 1 = 1 + tau_y always
            return
        else if (beta > huge(beta)) then
            eta_cr = 0.0_dp   ! spike: tau_m1 = tau_y = 1/2, always stick
            return
        end if
        f%c = exp_consts(beta)
        ! limits: eta -> 0: tau_m1 -> 2, tau_y -> 0 (margin 1); eta -> 1: both -> 1/2 (-1)
        call find_root(f, 0.0_dp, 1.0_dp, eta_cr, stat, errmsg, fa_known=1.0_dp, &
                       fb_known=-1.0_dp)
        if (stat == SEISPULSE_SUCCESS) stat = f%stat
    end subroutine eta_critical

    function stick_slip_margin_eval(self, x) result(y)
        class(stick_slip_margin), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: tau_y, tau_m, um, dug, vm
        integer :: regime, stat
        tau_y = exp_rise_time(x, self%c%beta)
        call one_slide(self%c, .true., tau_y, x, tau_m, um, dug, vm, regime, stat)
        if (stat /= SEISPULSE_SUCCESS) self%stat = stat
        y = tau_m - 1.0_dp - tau_y
    end function stick_slip_margin_eval

    !> The chapter's fit of the critical strength, Eq. 1.22 (fitted on -4 pi <= beta <= 4 pi,
    !> R^2 = 0.988; within about 0.03 of `eta_critical` there).
    elemental function eta_critical_regression(beta) result(eta_cr)
        real(dp), intent(in) :: beta  !! pulse shape
        real(dp) :: eta_cr
        eta_cr = 0.1_dp + 0.8_dp * exp(-exp(0.25_dp * beta - 0.15_dp))
    end function eta_critical_regression

    !> The chapter's fit of the full-cycle peak slip, Eq. 1.30: u_m/D_g = (1 - eta)^f(beta)
    !> with f = -9 + 12 e^(beta/20) (beta > 0), (3 - 0.9 beta)/(1 - 0.6 beta) (beta <= 0)
    !> and D_g = V_g t_d. An approximation (large relative errors at high eta, section 6).
    elemental function full_cycle_peak_regression(eta, beta) result(um_over_dg)
        real(dp), intent(in) :: eta   !! a_y/A_g > 0
        real(dp), intent(in) :: beta  !! pulse shape
        real(dp) :: um_over_dg
        real(dp) :: f
        if (beta > 0.0_dp) then
            f = -9.0_dp + 12.0_dp * exp(beta / 20.0_dp)
        else if (beta < -huge(beta)) then
            f = 1.5_dp
        else
            f = (3.0_dp - 0.9_dp * beta) / (1.0_dp - 0.6_dp * beta)
        end if
        if (eta < 1.0_dp) then
            um_over_dg = (1.0_dp - eta)**f
        else
            um_over_dg = 0.0_dp
        end if
    end function full_cycle_peak_regression

    ! ------------------------------------------------------------------------------
    ! Limit shapes in closed form (independent of the general route: used to check it)
    ! ------------------------------------------------------------------------------

    !> Rectangular half cycle (beta = -inf, Eq. 1.10a; Newmark 1965): tau_m = 1/eta,
    !> u_m = (1 - eta)/(2 eta), u_m/du_gm = (1 - eta)/(2 - eta), V_m/V_g = 1 - eta.
    elemental subroutine rectangle_half(eta, tau_m, um, ratio, vm)
        real(dp), intent(in) :: eta                 !! 0 < eta < 1
        real(dp), intent(out) :: tau_m  !! stop t_m/t_d
        real(dp), intent(out) :: um     !! slip u_m/(A_g t_d^2)
        real(dp), intent(out) :: ratio  !! u_m/du_gm (dimensionless)
        real(dp), intent(out) :: vm     !! peak sliding velocity V_m/V_g
        tau_m = 1.0_dp / eta
        um = (1.0_dp - eta) / (2.0_dp * eta)
        ratio = (1.0_dp - eta) / (2.0_dp - eta)
        vm = 1.0_dp - eta
    end subroutine rectangle_half

    !> Rectangular full cycle (section 5): the block always slips; tau_m1 = 2/(1 + eta),
    !> u_m1 = (1 - eta)/(1 + eta), tau_m2 = 4/(1 + eta), u_m2 = 2 eta (1 - eta)/(1 + eta)^2,
    !> u_res = ((1 - eta)/(1 + eta))^2.
    elemental subroutine rectangle_full(eta, tau_m1, um1, tau_m2, um2, ures)
        real(dp), intent(in) :: eta                 !! 0 < eta < 1
        real(dp), intent(out) :: tau_m1  !! forward stop t_m1/t_d
        real(dp), intent(out) :: um1     !! forward slip u_m1/(A_g t_d^2)
        real(dp), intent(out) :: tau_m2  !! reverse stop t_m2/t_d
        real(dp), intent(out) :: um2     !! reverse slip u_m2/(A_g t_d^2)
        real(dp), intent(out) :: ures    !! residual slip u_res/(A_g t_d^2)
        real(dp) :: q
        q = (1.0_dp - eta) / (1.0_dp + eta)
        tau_m1 = 2.0_dp / (1.0_dp + eta)
        um1 = q
        tau_m2 = 4.0_dp / (1.0_dp + eta)
        um2 = 2.0_dp * eta * q / (1.0_dp + eta)
        ures = q * q
    end subroutine rectangle_full

    !> Triangular half cycle (beta = 0, Eq. 1.10b with the sign of its last term corrected,
    !> doc/sliding.md Corrections 3; section 3): tau_y = eta/2, V_m/V_g = (1 - eta)^2, and
    !> free (eta <= 2 - sqrt 2): tau_m = (eta^2 + 2)/(4 eta), u_m = (12 - 24 eta + 12 eta^2 -
    !> eta^4)/(96 eta); forced: tau_m = 1 - eta/2 + (1 - eta)/sqrt 2, u_m = (3 + 2 sqrt 2)(1 -
    !> eta)^3/12.
    elemental subroutine triangle_half(eta, tau_y, tau_m, um, vm, regime)
        real(dp), intent(in) :: eta                 !! 0 < eta < 1
        real(dp), intent(out) :: tau_y  !! onset t_y/t_d
        real(dp), intent(out) :: tau_m  !! stop t_m/t_d
        real(dp), intent(out) :: um     !! slip u_m/(A_g t_d^2)
        real(dp), intent(out) :: vm     !! peak sliding velocity V_m/V_g
        integer, intent(out) :: regime  !! SLIDING_REGIME_FREE or SLIDING_REGIME_FORCED
        real(dp), parameter :: sqrt2 = sqrt(2.0_dp)
        tau_y = 0.5_dp * eta
        vm = (1.0_dp - eta)**2
        if (eta <= 2.0_dp - sqrt2) then
            regime = SLIDING_REGIME_FREE
            tau_m = (eta * eta + 2.0_dp) / (4.0_dp * eta)
            um = (12.0_dp - 24.0_dp * eta + 12.0_dp * eta**2 - eta**4) / (96.0_dp * eta)
        else
            regime = SLIDING_REGIME_FORCED
            tau_m = 1.0_dp - 0.5_dp * eta + (1.0_dp - eta) / sqrt2
            um = (3.0_dp + 2.0_dp * sqrt2) * (1.0_dp - eta)**3 / 12.0_dp
        end if
    end subroutine triangle_half

    !> V_m/V_g under the spike (beta -> +inf): 1 - eta (1 - ln eta), the lower bound over all
    !> shapes (section 3); the slip itself vanishes with the pulse area.
    elemental function spike_velocity_ratio(eta) result(vm)
        real(dp), intent(in) :: eta  !! 0 < eta <= 1
        real(dp) :: vm
        vm = spike_vm(eta, eta)
    end function spike_velocity_ratio

    ! ------------------------------------------------------------------------------
    ! Inclined plane, SI entry point
    ! ------------------------------------------------------------------------------

    !> Direction-dependent resistances of a block of friction mu on a plane of slope lambda,
    !> for a pulse of amplitude A_g at angle xi to the horizontal (Eq. 1.31):
    !> eta1,2 = (mu g/A_g) (cos lambda -+ sin lambda/mu)/K1,2 with the along-plane factors
    !> K1,2 = cos(lambda - xi) +- mu sin(lambda - xi) (section 7): the along-plane slip is
    !> K times the slip of the dimensionless problem. eta = +inf when K <= 0 (the pulse
    !> cannot drive the block that way).
    !> xi_deg is optional (default 0 as in Python's `sliding.inclined_resistances`);
    !> when omitted, pass eta1, eta2, k1, k2 and stat by keyword.
    subroutine inclined_resistances(mu, ag_over_g, slope_deg, xi_deg, eta1, eta2, k1, k2, &
                                    stat, errmsg)
        real(dp), intent(in) :: mu                            !! friction coefficient > 0
        real(dp), intent(in) :: ag_over_g                     !! A_g/g > 0
        real(dp), intent(in) :: slope_deg                     !! lambda in [0, 90) deg
        !> xi in [-90, 90] deg; default 0 (horizontal excitation)
        real(dp), intent(in), optional :: xi_deg
        real(dp), intent(out) :: eta1                         !! downhill resistance / A_g
        real(dp), intent(out) :: eta2                         !! uphill resistance / A_g
        real(dp), intent(out) :: k1                           !! downhill along-plane factor
        real(dp), intent(out) :: k2                           !! uphill along-plane factor
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: lam, dl, eta, inf
        real(dp) :: xi_in
        xi_in = optval(xi_deg, 0.0_dp)
        inf = ieee_value(inf, ieee_positive_inf)
        eta1 = ieee_value(eta1, ieee_quiet_nan)
        eta2 = eta1
        k1 = eta1
        k2 = eta1
        stat = SEISPULSE_SUCCESS
        if (outside(mu, 0.0_dp, inf, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mu = '//real_str(mu) &
                           //': must be a finite friction coefficient > 0')
        else if (outside(ag_over_g, 0.0_dp, inf, .true., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag = '//real_str(ag_over_g) &
                           //': must be a finite pulse amplitude > 0 (in g)')
        else if (outside(slope_deg, 0.0_dp, 90.0_dp, .false., .true.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'slope_deg = ' &
                           //real_str(slope_deg)//': must be in [0, 90) degrees')
        else if (outside(xi_in, -90.0_dp, 90.0_dp, .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi_deg = ' &
                           //real_str(xi_in)//': must be in [-90, 90] degrees')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        lam = slope_deg * (pi / 180.0_dp)
        if (.not. (tan(lam) < mu)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'slope_deg = ' &
                //real_str(slope_deg)//': steeper than the friction angle atan(mu) = ' &
                //real_str(atan(mu) * (180.0_dp / pi))//' deg; the block slides without' &
                //' any excitation (statically unstable slope)')
            return
        end if
        dl = lam - xi_in * (pi / 180.0_dp)
        eta = mu / ag_over_g
        k1 = cos(dl) + mu * sin(dl)
        k2 = cos(dl) - mu * sin(dl)
        eta1 = inf
        eta2 = inf
        if (k1 > 0.0_dp) eta1 = eta * (cos(lam) - sin(lam) / mu) / k1
        if (k2 > 0.0_dp) eta2 = eta * (cos(lam) + sin(lam) / mu) / k2
        k1 = max(k1, 0.0_dp)
        k2 = max(k2, 0.0_dp)
    end subroutine inclined_resistances

    !> A block of friction mu on a plane of slope lambda under an exponential pulse of
    !> amplitude A_g (in g) and half-duration t_d (s) acting at angle xi to the horizontal,
    !> positive downhill: times in s, slips in m along the plane (with the factors K of
    !> section 7 when along_plane; without them, as in the chapter's example 1.9.2).
    !> The arguments from full to g are optional with the defaults of Python's
    !> `sliding.block`; when one is omitted, pass res and stat by keyword.
    subroutine block_response(mu, ag_over_g, td, beta, full, slope_deg, xi_deg, &
                              static_factor, static_reverse, along_plane, g, res, stat, errmsg)
        real(dp), intent(in) :: mu                            !! friction coefficient > 0
        real(dp), intent(in) :: ag_over_g                     !! A_g/g > 0
        real(dp), intent(in) :: td                            !! t_d, one lobe (s) > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        !> full cycle (.true.) or one lobe; default .false.
        logical, intent(in), optional :: full
        !> lambda in [0, 90) deg; default 0 (horizontal plane)
        real(dp), intent(in), optional :: slope_deg
        !> xi in [-90, 90] deg; default 0 (horizontal excitation)
        real(dp), intent(in), optional :: xi_deg
        !> a >= 1 (static over kinetic friction); default 1
        real(dp), intent(in), optional :: static_factor
        !> a also at the reverse onset; default .false.
        logical, intent(in), optional :: static_reverse
        !> apply K1, K2; default .true.
        logical, intent(in), optional :: along_plane
        !> gravity (m/s^2) > 0; default STANDARD_GRAVITY (9.80665)
        real(dp), intent(in), optional :: g
        type(sliding_block_t), intent(out) :: res                     !! the response (SI)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: eta1, eta2, k1, k2
        logical :: full_in, reverse_in, along_in
        real(dp) :: slope_in, xi_in, static_in, g_in
        full_in = optval(full, .false.)
        slope_in = optval(slope_deg, 0.0_dp)
        xi_in = optval(xi_deg, 0.0_dp)
        static_in = optval(static_factor, 1.0_dp)
        reverse_in = optval(static_reverse, .false.)
        along_in = optval(along_plane, .true.)
        g_in = optval(g, STANDARD_GRAVITY)
        call inclined_resistances(mu, ag_over_g, slope_in, xi_in, eta1, eta2, k1, k2, &
                                  stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. along_in) then
            k1 = 1.0_dp
            k2 = 1.0_dp
        end if
        call block_response_eta(eta1, eta2, k1, k2, ag_over_g, td, beta, full_in, static_in, &
                                reverse_in, g_in, res, stat, errmsg)
    end subroutine block_response

    !> The same from the resistances eta1, eta2 (over A_g) and the along-plane factors
    !> k1, k2 (1 on a flat plane or to leave them out).
    subroutine block_response_eta(eta1, eta2, k1, k2, ag_over_g, td, beta, full, &
                                  static_factor, static_reverse, g, res, stat, errmsg)
        real(dp), intent(in) :: eta1                          !! downhill a_y1/A_g > 0
        real(dp), intent(in) :: eta2                          !! uphill a_y2/A_g > 0
        real(dp), intent(in) :: k1                            !! downhill along-plane factor
        real(dp), intent(in) :: k2                            !! uphill along-plane factor
        real(dp), intent(in) :: ag_over_g                     !! A_g/g > 0
        real(dp), intent(in) :: td                            !! t_d, one lobe (s) > 0
        real(dp), intent(in) :: beta                          !! pulse shape (-), not NaN
        logical, intent(in) :: full                           !! full cycle
        real(dp), intent(in) :: static_factor                 !! a >= 1
        logical, intent(in) :: static_reverse                 !! a also at the reverse onset
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        type(sliding_block_t), intent(out) :: res                     !! the response (SI)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: ag, ulen, vlen
        type(exp_consts_t) :: c
        type(half_cycle_t) :: h
        type(full_cycle_t) :: f
        stat = SEISPULSE_SUCCESS
        if (outside(ag_over_g, 0.0_dp, huge(g), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag = '//real_str(ag_over_g) &
                           //': must be a finite pulse amplitude > 0 (in g)')
        else if (outside(td, 0.0_dp, huge(td), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'td = '//real_str(td) &
                           //': must be a finite duration > 0 (s)')
        else if (outside(g, 0.0_dp, huge(g), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g) &
                           //': must be a finite acceleration > 0 (m/s2)')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        if (full) then
            call full_cycle(eta1, eta2, beta, static_factor, static_reverse, f, stat, errmsg)
        else
            ! a half cycle drives the block one way only
            call half_cycle(eta1, beta, static_factor, h, stat, errmsg)
            f%mode = SLIDING_MODE_NO_SLIDING
            if (h%regime /= SLIDING_REGIME_NONE) f%mode = SLIDING_MODE_UNILATERAL
            f%tau_y1 = h%tau_y
            f%tau_m1 = h%tau_m
            f%um1 = h%um
            f%ures = h%um
            f%vm1 = h%vm
            f%tau_y2 = ieee_value(f%tau_y2, ieee_quiet_nan)
            f%tau_m2 = f%tau_y2
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        ag = ag_over_g * g
        ulen = ag * td * td
        c = exp_consts(beta)
        vlen = ag * td * c%vg
        res%mode = f%mode
        res%eta1 = eta1
        res%eta2 = eta2
        res%t_y1 = f%tau_y1 * td
        res%t_m1 = f%tau_m1 * td
        res%t_y2 = f%tau_y2 * td
        res%t_m2 = f%tau_m2 * td
        res%u_m1 = k1 * f%um1 * ulen
        res%u_m2 = k2 * f%um2 * ulen
        res%u_res = res%u_m1 - res%u_m2
        res%v_m1 = k1 * f%vm1 * vlen
        res%v_m2 = k2 * f%vm2 * vlen
    end subroutine block_response_eta

    ! ------------------------------------------------------------------------------
    ! Names and checks
    ! ------------------------------------------------------------------------------

    !> 'none', 'forced' or 'free'.
    pure function sliding_regime_name(regime) result(name)
        integer, intent(in) :: regime  !! SLIDING_REGIME_*
        character(len=len_trim(sliding_regime_name_text(regime))) :: name
        name = sliding_regime_name_text(regime)
    end function sliding_regime_name

    !> sliding_regime_name(regime) padded with blanks.
    pure function sliding_regime_name_text(regime) result(name)
        integer, intent(in) :: regime
        character(len=64) :: name
        if (regime >= 0 .and. regime <= 2) then
            name = trim(regime_names(regime))
        else
            name = 'unknown'
        end if
    end function sliding_regime_name_text

    !> 'no_sliding', 'unilateral', 'stick', 'slip', 'stuck' or 'reverse_only'.
    pure function sliding_mode_name(mode) result(name)
        integer, intent(in) :: mode  !! SLIDING_MODE_*
        character(len=len_trim(sliding_mode_name_text(mode))) :: name
        name = sliding_mode_name_text(mode)
    end function sliding_mode_name

    !> sliding_mode_name(mode) padded with blanks.
    pure function sliding_mode_name_text(mode) result(name)
        integer, intent(in) :: mode
        character(len=64) :: name
        if (mode >= 0 .and. mode <= 5) then
            name = trim(mode_names(mode))
        else
            name = 'unknown'
        end if
    end function sliding_mode_name_text

    !> Arguments of a half-cycle case, in this order: eta, beta, static_factor.
    subroutine check_half(eta, beta, static_factor, stat, errmsg)
        real(dp), intent(in) :: eta, beta, static_factor
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_eta(eta, 'eta', stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_static(static_factor, stat, errmsg)
    end subroutine check_half

    !> Arguments of a full-cycle case, in this order: eta1, eta2, beta, static_factor.
    subroutine check_full(eta1, eta2, beta, static_factor, stat, errmsg)
        real(dp), intent(in) :: eta1, eta2, beta, static_factor
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_eta(eta1, 'eta1', stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_eta(eta2, 'eta2', stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_beta(beta, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) call check_static(static_factor, stat, errmsg)
    end subroutine check_full

    subroutine check_eta(eta, name, stat, errmsg)
        real(dp), intent(in) :: eta
        character(len=*), intent(in) :: name
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        ! +inf is allowed: no sliding that way
        if (outside(eta, 0.0_dp, ieee_value(eta, ieee_positive_inf), .true., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//' = '//real_str(eta) &
                           //': must be > 0 (a_y/A_g; eta >= 1 means no sliding)')
    end subroutine check_eta

    subroutine check_static(a, stat, errmsg)
        real(dp), intent(in) :: a
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(a, 1.0_dp, huge(a), .false., .false.)) call set_error(stat, &
            errmsg, SEISPULSE_INVALID_INPUT, 'static_factor = '//real_str(a) &
            //': must be a finite number >= 1 (static over kinetic friction)')
    end subroutine check_static

end module seispulse_sliding_closed
