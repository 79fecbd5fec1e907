!> Linear oscillator under prescribed base motion, in closed form (doc/oscillator.md).
!>
!> Model: natural period T (omega = 2 pi/T), viscous damping ratio zeta (0 <= zeta < 1; the
!> book's gamma = 2 zeta), relative displacement z, ground acceleration a_g, from rest:
!>     z'' + 2 zeta omega z' + omega^2 z = -a_g(t),
!>     a_abs = a_g + z'' = -(2 zeta omega z' + omega^2 z).
!> SI throughout: a_g, a_abs in m/s^2, z in m, z' in m/s, t and T in s. A positive period
!> must be finite and >= min_period (1e-60 s, seispulse_sdof_sim: omega^2 stays finite).
!>
!> Book forms (undamped unless stated; equation numbers of doc/oscillator.md):
!> * `dynamic_coefficient`: Eq. 2.17 (gamma = 0, signed 1/(1 - r^2)), Eq. 2.20 with the
!>   square root restored (hysteretic, the default) or the viscous form; beta(r = 1) = 1/gamma;
!>   the cosine law's coefficient 2|beta| (after Eq. 2.21), the from-rest maximum only when
!>   gamma = 0 (with damping it is not: zeta = 0.05, r = 1 reaches 1/gamma = 10, not 20).
!> * `harmonic_response`: Delta = Delta0 sin(theta t) or cos(theta t), W0 = Delta0 theta^2, so
!>   a_g = -W0 sin(theta t) or -W0 cos(theta t); steady state (Eq. 2.17, viscous damped) or the
!>   exact solution from rest (Eq. 2.21 with cos(omega t), the printed sin(omega t) is an erratum).
!> * `rect_pulse_response`: Fig. 2.6, Eq. 2.22/2.23 with the minus sign restored, any t1.
!> * `beta_pulse`: the book's 1 + 2 pi t1/T (an additive upper bound) or the exact 2 sin(pi t1/T).
!> * `impulse_max`, `impulse_response`: Eq. 2.24/2.25, and the damped impulse maximum.
!>
!> Response to every pulse of seispulse_pulses (`sdof_pulse_response`, `sdof_pulse_peaks`,
!> `sdof_pulse_spectrum`). With the phase sigma = omega t, lambda = -zeta + i sqrt(1 - zeta^2)
!> and omega_d = omega sqrt(1 - zeta^2), the state is the complex velocity V with
!> z = Re V/omega, z' = Re(lambda V), a_abs = omega Re(lambda^2 V) (velocity units keep z and
!> a_abs representable for very long and very short periods alike). Between the breaks of
!> the pulse (segments of duration d, L = omega d, fraction s in [0, 1], sigma = L s, tau = d s)
!>     V(s) = e^(lambda sigma) V(0) + (i/sqrt(1 - zeta^2)) K(s)/omega,
!>     K/omega = int_0^tau e^(lambda omega (tau - u)) a_g(u) du,
!> and a_g is a sum of terms whose kernels are divided differences of exp (each evaluated
!> without cancellation or overflow, exact at resonance):
!>     C e^(M (s - v))        ->  C tau e[lambda sigma - M v, M (s - v)]    (real C, M; v = 0 or 1
!>                                so that the exponent is <= 0 on the segment: no overflow)
!>     Re(C e^(i kappa s))    ->  cos and sin parts, tau (e1 + e2)/2 and tau kappa s e[x, iks, -iks]
!>     C s phi_1(R s)         ->  C tau s e[lambda sigma, R s, 0]   (the "expm1 ramp")
!> Where sqrt(1 - zeta^2) sigma = omega_d t < 1, Re V (the displacement) is not taken from
!> Im K/sqrt(1 - zeta^2) (Im K keeps only ~omega_d t of the digits of K: very long periods,
!> the start of a segment, and zeta -> 1, where the relative error would be
!> eps/sqrt(1 - zeta^2)) but from divided differences over the conjugate pair, the impulse
!> response being sigma e[lambda sigma, conj(lambda) sigma]: -C tau sigma e[x, conj(x), y]
!> per term, -C tau sigma s e[x, conj(x), R s, 0] for the ramp (a general third divided
!> difference: Taylor series in the unit disk, else the quotient over the farthest pair).
!> Per kind:
!> * exponential (doc/pulses.md Eq. 1.1b), each half lobe: |beta| <= 1 the expm1 ramp with the
!>   bounded factor 1/phi_1(beta) (beta = 0 is the triangle); beta > 1 the exponential
!>   referenced at the peak, [e^(beta (s - 1)) - e^-beta]/(1 - e^-beta); beta < -1 referenced at
!>   the start, [1 - e^(beta s)]/(1 - e^beta); the falling half is the rising one with s -> 1 - s
!>   (for |beta| <= 1 written as the constant A minus a ramp, A [1 - e^beta s phi_1(-beta s)/
!>   phi_1(beta)]), the second lobe negated. Every term is bounded by a few |A|, but where
!>   a_g -> 0 at the zero end of a half lobe the terms cancel: there a_g (and so K) is accurate
!>   to ~eps |A| absolutely, not relative to the small a_g. beta = -inf is the box, beta = +inf
!>   the spike (no area: zero response); a huge finite beta gives the impulse of area
!>   A t_d/beta at t_d/2 (and 3 t_d/2 negated).
!> * half_sine, sine_cycle, cosine_cycle, mavroeidis_papageorgiou: sums of sinusoids (M&P:
!>   three, the derivative of (A/2)(1 + cos(2 pi f x/gamma)) cos(2 pi f x + nu)); n sine or
!>   cosine cycles are one segment of n T with A sin(2 pi n s) or A cos(2 pi n s), the same
!>   closed form as one cycle (the peak search needs n <= 32768: 32 scan steps per cycle).
!> * rectangular: a constant; triangular: two linear ramps.
!> * ricker: no elementary closed form (the complex error function would be needed); its
!>   Duhamel integral is evaluated by composite 20-node Gauss-Legendre on equal panels no
!>   longer than min(T, 1/f_p)/32 (rounding-level accurate: the integrand is entire), the
!>   state carried exactly from panel to panel; the wavelet is cut at
!>   x = pi f_p (t - t0) = -10 and +10 as in seispulse_pieces (|a_g| < 1e-40 a_p outside).
!>   At most 2^20 panels: periods below 32 (window)/2^20 are refused with a message.
!> After the pulse the response is the free vibration V = e^(lambda sigma) V_end, at any t.
!>
!> Peaks (`sdof_pulse_peaks`, `sdof_pulse_spectrum`): the maxima of |z|, |z'|, |a_abs| over
!> all t >= 0. In each segment a scan brackets the sign changes of z' = Re(lambda V),
!> z'' = omega Re(lambda^2 V) - a_g and d a_abs/dt = omega (omega Re(lambda^3 V) + 2 zeta a_g).
!> Scan step: <= T/32, <= segment/64, <= 1/32 of the shortest period of a sinusoidal term,
!> and for exponential half lobes with |beta| > 16 a scan graded from the sharp end (first
!> step t_d/(8|beta|), then x1.25 per step; the first step is floored at 1e-12 of the half
!> lobe, below which a spike is not resolved). At most 2^20 steps per segment: a period
!> shorter than 32 (longest segment)/2^20 = segment/32768 (e.g. 6.1e-5 s for a 2 s rectangle)
!> is refused with a message naming it and the shortest period allowed, as is an M&P pulse
!> with gamma > 32767 (more than 32768 cycles in its window); a coarser scan would alias.
!> The scan values come from
!> the exact one-step recurrence (kernel constants cached per step length; cheap) and only
!> steer the search. Ricker: the scan points are the panel ends. Each bracket's extremum is
!> estimated by the cubic Hermite interpolant of its two scan points; brackets whose estimate
!> is within 1% of the best value found are refined by Brent's method (seispulse_roots:
!> proven bracket, guaranteed termination) and the value is taken at the root, evaluated
!> directly. Segment ends (kinks where a_g jumps) and the best interior sample, evaluated
!> directly, are candidates too. After the pulse the maximum of a damped sinusoid on
!> [t_end, inf) is at t_end or at its first stationary point, both closed form.
!> Period 0 in a spectrum is the rigid oscillator: sd = sv = 0, sa = the peak |a_g| (PGA).
!> For a pulse whose a_g jumps (rectangular, cosine_cycle, the box) the limit T -> 0+ of sa
!> is larger than the PGA: the step overshoot, up to 2 PGA undamped (1.8588 PGA at
!> T = 1e-4 s, zeta = 0.05 for a rectangle); sa is not continuous at T = 0 for those pulses.
module seispulse_sdof_closed
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                set_error
    use seispulse_checks, only: outside, check_finite_times
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: expm1, exp_phis, phi1, sin_pi, cos_pi, pi
    use seispulse_divided_differences, only: cexp_dd1, cexp_dd2, cexp_dd3
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_sdof_sim, only: sdof_validate, min_period
    use seispulse_pulses, only: pulse_t, pulse_validate, PULSE_EXPONENTIAL, PULSE_HALF_SINE, &
                                PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, PULSE_RECTANGULAR, &
                                PULSE_TRIANGULAR, PULSE_RICKER, PULSE_MP, pulse_peak_accel, &
                                ricker_accel, ricker_window, mp_terms
    implicit none
    private

    public :: dynamic_coefficient, harmonic_response, rect_pulse_response, beta_pulse, &
              impulse_max, impulse_response
    public :: sdof_pulse_response, sdof_pulse_peaks, sdof_pulse_spectrum
    public :: BETA_HYSTERETIC, BETA_VISCOUS, HARMONIC_SINE, HARMONIC_COSINE, &
              BETA_PULSE_TEXTBOOK, BETA_PULSE_EXACT

    integer, parameter :: BETA_HYSTERETIC = 1      !! Eq. 2.20: 1/sqrt((1 - r^2)^2 + gamma^2)
    integer, parameter :: BETA_VISCOUS = 2         !! 1/sqrt((1 - r^2)^2 + gamma^2 r^2)
    integer, parameter :: HARMONIC_SINE = 1        !! Delta0 sin(theta t): a_g = -W0 sin(theta t)
    integer, parameter :: HARMONIC_COSINE = 2      !! Delta0 cos(theta t): a_g = -W0 cos(theta t)
    integer, parameter :: BETA_PULSE_TEXTBOOK = 1  !! the book's 1 + 2 pi t1/T (upper bound)
    integer, parameter :: BETA_PULSE_EXACT = 2     !! 2 sin(pi t1/T) for t1 <= T/2, else 2

    real(dp), parameter :: two_pi = 2.0_dp * pi
    !> Half lobes with |beta| at most this use the expm1-ramp form (no 1/beta blow-up).
    real(dp), parameter :: beta_small = 1.0_dp
    integer, parameter :: max_ricker_panels = 2**20
    !> Ricker panels: at most min(T, 1/f_p)/ricker_panels_per long.
    real(dp), parameter :: ricker_panels_per = 32.0_dp
    !> Peak scan: at most max_scan steps per segment, at least scan_per_cycle per period of
    !> the oscillator and of every sinusoidal term (shorter periods are refused).
    integer, parameter :: max_scan = 2**20
    real(dp), parameter :: scan_per_cycle = 32.0_dp
    real(dp), parameter :: grade_factor = 1.25_dp
    real(dp), parameter :: grade_floor = 1.0e-12_dp
    !> Brackets whose Hermite estimate is within this fraction of the best value are refined.
    real(dp), parameter :: prune_margin = 1.0e-2_dp
    integer, parameter :: max_terms = 4

    !> 20-point Gauss-Legendre nodes (positive half) and weights on [-1, 1].
    real(dp), parameter :: gl_x(10) = [0.07652652113349733375464_dp, 0.2277858511416450780805_dp, &
        0.3737060887154195606725_dp, 0.5108670019508270980044_dp, 0.6360536807265150254528_dp, &
        0.7463319064601507926143_dp, 0.8391169718222188233945_dp, 0.9122344282513259058678_dp, &
        0.9639719272779137912677_dp, 0.9931285991850949247861_dp]
    real(dp), parameter :: gl_w(10) = [0.1527533871307258506981_dp, 0.1491729864726037467878_dp, &
        0.1420961093183820513293_dp, 0.1316886384491766268985_dp, 0.1181945319615184173124_dp, &
        0.1019301198172404350368_dp, 0.08327674157670474872476_dp, 0.06267204833410906356951_dp, &
        0.04060142980038694133104_dp, 0.01761400713915211831186_dp]

    !> The oscillator in dimensionless time sigma = omega t.
    type :: osc_t
        real(dp) :: omega = 1.0_dp              !! 2 pi/T (rad/s)
        real(dp) :: zeta = 0.0_dp               !! damping ratio
        real(dp) :: wd = 1.0_dp                 !! sqrt(1 - zeta^2)
        complex(dp) :: lam = (0.0_dp, 1.0_dp)   !! -zeta + i wd
        complex(dp) :: lam2 = (-1.0_dp, 0.0_dp) !! lam^2
        complex(dp) :: lam3 = (0.0_dp, -1.0_dp) !! lam^3
    end type osc_t

    !> One segment of the ground acceleration between breaks, s = (t - ta)/dur in [0, 1]:
    !> a_g = sum ce e^(me (s - ve)) + sum Re(cs e^(i ks s)) + cr s phi_1(rr s), or the Ricker
    !> wavelet by quadrature.
    type :: seg_t
        real(dp) :: ta = 0.0_dp     !! start time (s)
        real(dp) :: dur = 0.0_dp    !! duration (s)
        real(dp) :: len = 0.0_dp    !! omega dur
        integer :: nexp = 0
        real(dp) :: ce(max_terms) = 0.0_dp, me(max_terms) = 0.0_dp, ve(max_terms) = 0.0_dp
        integer :: nsin = 0
        complex(dp) :: cs(max_terms) = (0.0_dp, 0.0_dp)
        real(dp) :: ks(max_terms) = 0.0_dp
        logical :: has_r = .false.
        real(dp) :: cr = 0.0_dp, rr = 0.0_dp
        logical :: quad = .false.   !! Ricker panel
        real(dp) :: hmax = 1.0_dp / 64.0_dp  !! largest scan step (fraction of the segment)
        real(dp) :: grade = 0.0_dp  !! > 0: exponent rate |beta| per segment, graded scan
        integer :: sharp = 0        !! graded scan: sharp end at s = 0 (1) or s = 1 (2)
        complex(dp) :: wa = (0.0_dp, 0.0_dp)  !! state at the start
    end type seg_t

    !> The oscillator under one pulse: closed-form segments, or (Ricker) quadrature panels
    !> of equal length with the state at each panel end.
    type :: model_t
        type(osc_t) :: osc
        type(pulse_t) :: p
        integer :: nseg = 0                       !! segments (or panels)
        type(seg_t), allocatable :: seg(:)        !! closed-form segments
        logical :: ricker = .false.               !! panels instead of segments
        real(dp) :: ts = 0.0_dp                   !! Ricker: start of the first panel (s)
        real(dp) :: hp = 0.0_dp                   !! Ricker: panel length (s)
        complex(dp), allocatable :: wp(:)         !! Ricker: state at the panel ends, 0:nseg
        real(dp) :: t_end = 0.0_dp                !! end of the last segment (s)
        complex(dp) :: w_end = (0.0_dp, 0.0_dp)   !! state there
    end type model_t

    !> Kernel constants of one scan step of length h (fraction of the segment), cached.
    type :: step_t
        real(dp) :: h = -1.0_dp
        complex(dp) :: eh = (0.0_dp, 0.0_dp)
        complex(dp) :: kexp(max_terms) = (0.0_dp, 0.0_dp)
        complex(dp) :: kcos(max_terms) = (0.0_dp, 0.0_dp)
        complex(dp) :: ksin(max_terms) = (0.0_dp, 0.0_dp)
        complex(dp) :: kra = (0.0_dp, 0.0_dp), krb = (0.0_dp, 0.0_dp)
    end type step_t

    !> The slope of z, z' or a_abs on one segment, for Brent's method.
    type, extends(scalar_function) :: slope_fn
        type(osc_t) :: osc
        type(seg_t) :: seg
        type(pulse_t) :: p
        integer :: which = 1
    contains
        procedure :: eval => slope_eval
    end type slope_fn

    type :: bracket_t
        integer :: seg = 0, which = 0
        real(dp) :: sa = 0.0_dp, sb = 0.0_dp, est = 0.0_dp
    end type bracket_t

contains

    ! ==================================================================================
    ! Book forms
    ! ==================================================================================

    !> Dynamic coefficient of harmonic base motion (Eq. 2.17, 2.20): r = theta/omega,
    !> gamma = 2 zeta. gamma = 0: the signed 1/(1 - r^2) (negative above resonance);
    !> BETA_HYSTERETIC (the book's Eq. 2.20, square root restored): 1/sqrt((1 - r^2)^2 + gamma^2);
    !> BETA_VISCOUS: 1/sqrt((1 - r^2)^2 + gamma^2 r^2). Both give 1/gamma at r = 1.
    !> r = 1 with gamma = 0 is SEISPULSE_SINGULAR. beta_cos = 2|beta|: for gamma = 0 the cosine
    !> law's coefficient from rest (after Eq. 2.21), the supremum of |z| omega^2/W0 of
    !> (W0 beta/omega^2)(cos theta t - cos omega t). For gamma > 0 it is only the book's rule
    !> 2|beta| applied to the damped beta, NOT the damped from-rest maximum (zeta = 0.05, r = 1:
    !> from rest |z| omega^2/W0 tends to 1/gamma = 10, while 2|beta| = 20); use
    !> harmonic_response (HARMONIC_COSINE, transient) for the damped history.
    subroutine dynamic_coefficient(ratio, gamma, model, beta, stat, errmsg, beta_cos)
        real(dp), intent(in) :: ratio                         !! r = theta/omega, >= 0
        real(dp), intent(in) :: gamma                         !! damping parameter 2 zeta, >= 0
        integer, intent(in) :: model                          !! BETA_HYSTERETIC or BETA_VISCOUS
        real(dp), intent(out) :: beta                         !! dynamic coefficient
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: beta_cos           !! 2 |beta| (cosine law; from rest
                                                              !! only for gamma = 0)
        real(dp) :: d
        beta = 0.0_dp
        if (present(beta_cos)) beta_cos = 0.0_dp
        call check_ratio(ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(gamma, 0.0_dp, huge(1.0_dp), .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = '//real_str(gamma) &
                           //': must be a finite number >= 0 (gamma = 2 zeta)')
            return
        end if
        if (model /= BETA_HYSTERETIC .and. model /= BETA_VISCOUS) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model = '//int_str(model) &
                           //': must be 1 (hysteretic, Eq. 2.20) or 2 (viscous)')
            return
        end if
        stat = SEISPULSE_SUCCESS
        d = one_minus_r2(ratio)
        if (.not. (gamma > 0.0_dp)) then
            if (.not. (abs(d) > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_SINGULAR, 'ratio = 1, gamma = 0: the ' &
                               //'undamped dynamic coefficient is infinite at resonance ' &
                               //'(theta = omega); give gamma > 0')
                return
            end if
            beta = 1.0_dp / d                      ! Eq. 2.17, signed
        else if (model == BETA_HYSTERETIC) then
            beta = 1.0_dp / hypot(d, gamma)        ! Eq. 2.20
        else
            beta = 1.0_dp / hypot(d, gamma * ratio)
        end if
        if (present(beta_cos)) beta_cos = 2.0_dp * abs(beta)
    end subroutine dynamic_coefficient

    !> Response to harmonic base motion (Sec. 2.3.2): law HARMONIC_SINE, a_g = -W0 sin(theta t)
    !> (Eq. 2.15/2.16), or HARMONIC_COSINE, a_g = -W0 cos(theta t), with W0 = Delta0 theta^2.
    !> transient: the exact solution from rest at t = 0 (zero for t < 0): for the undamped sine
    !> law (W0 beta/omega^2)(sin theta t - r sin omega t), for the cosine law Eq. 2.21
    !> (W0 beta/omega^2)(cos theta t - cos omega t); exact and without loss of digits at and
    !> near resonance (t sin(omega t) limit). Otherwise the steady state (Eq. 2.17 when
    !> undamped, the viscous steady state when damped); undamped steady state at r = 1 is
    !> SEISPULSE_SINGULAR.
    subroutine harmonic_response(t, w0, period, ratio, damping, law, transient, z, v, a_abs, &
                                 stat, errmsg)
        real(dp), intent(in) :: t(:)                          !! times (s), finite
        real(dp), intent(in) :: w0                            !! W0, base acceleration (m/s^2)
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(in) :: ratio                         !! r = theta/omega, >= 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        integer, intent(in) :: law                            !! HARMONIC_SINE or HARMONIC_COSINE
        logical, intent(in) :: transient                      !! from rest (else steady state)
        real(dp), intent(out) :: z(:)                         !! relative displacement (m)
        real(dp), intent(out) :: v(:)                         !! relative velocity (m/s)
        real(dp), intent(out) :: a_abs(:)                     !! absolute acceleration (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(osc_t) :: osc
        type(seg_t) :: seg
        complex(dp) :: c, zhat, w, ph
        real(dp) :: ag, d
        integer :: i
        call check_sizes(t, z, v, a_abs, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_amplitude(w0, 'w0', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_oscillator(period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_ratio(ratio, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (law /= HARMONIC_SINE .and. law /= HARMONIC_COSINE) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'law = '//int_str(law) &
                           //': must be 1 (sine) or 2 (cosine)')
            return
        end if
        call check_finite_times(t, 't', stat, errmsg, ' (s)')
        if (stat /= SEISPULSE_SUCCESS) return
        osc = make_osc(period, damping)
        ! a_g = Re(c e^(i theta t)): -W0 sin = Re(i W0 e^(i theta t)), -W0 cos = Re(-W0 e^(...))
        if (law == HARMONIC_SINE) then
            c = cmplx(0.0_dp, w0, dp)
        else
            c = cmplx(-w0, 0.0_dp, dp)
        end if
        if (.not. transient) then
            ! steady state Z = Re(zhat e^(i r sigma)): (1 - r^2 + 2 i zeta r) zhat = -c
            ! (Eq. 2.17 when undamped, the viscous steady state when damped)
            d = one_minus_r2(ratio)
            if (.not. (damping > 0.0_dp .or. abs(d) > 0.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_SINGULAR, 'ratio = 1, damping = 0: the ' &
                               //'undamped steady state does not exist at resonance (use ' &
                               //'transient = true: it grows like t sin(omega t))')
                return
            end if
            zhat = -c / cmplx(d, 2.0_dp * damping * ratio, dp)
            do i = 1, size(t)
                ph = phase(ratio * osc%omega * t(i))
                w = zhat * ph
                z(i) = real(w, dp) / osc%omega / osc%omega
                v(i) = real(cmplx(0.0_dp, ratio, dp) * w, dp) / osc%omega
                a_abs(i) = -(2.0_dp * damping * real(cmplx(0.0_dp, ratio, dp) * w, dp) &
                             + real(w, dp))
            end do
            return
        end if
        ! from rest (Eq. 2.21 with cos(omega t) for the undamped cosine law): the forcing
        ! a_g = Re(c e^(i r sigma)) as one sinusoidal segment [0, t], exact at resonance
        seg%nsin = 1
        seg%cs(1) = c
        do i = 1, size(t)
            if (.not. (t(i) > 0.0_dp)) cycle
            seg%dur = t(i)
            seg%len = osc%omega * t(i)
            seg%ks(1) = ratio * seg%len
            call seg_state(osc, seg, pulse_t(), 1.0_dp, w, ag)
            call outputs(osc, w, z(i), v(i), a_abs(i))
        end do
    end subroutine harmonic_response

    !> Undamped response to the rectangular acceleration pulse a_g = W0 on 0 <= t < t1 (Fig. 2.6),
    !> any t1: during the pulse z = -(W0/omega^2)(1 - cos omega t) (written 2 sin^2(omega t/2));
    !> after it Eq. 2.23 with its minus sign, z = -(2 W0/omega^2) sin(omega t1/2)
    !> sin(omega (t - t1/2)). a_abs = -omega^2 z. Zero for t < 0.
    subroutine rect_pulse_response(t, w0, t1, period, z, v, a_abs, stat, errmsg)
        real(dp), intent(in) :: t(:)                          !! times (s), finite
        real(dp), intent(in) :: w0                            !! W0, pulse acceleration (m/s^2)
        real(dp), intent(in) :: t1                            !! pulse duration t1 (s), > 0
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(out) :: z(:)                         !! relative displacement (m)
        real(dp), intent(out) :: v(:)                         !! relative velocity (m/s)
        real(dp), intent(out) :: a_abs(:)                     !! absolute acceleration (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: om, s1, x
        integer :: i
        call check_sizes(t, z, v, a_abs, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_amplitude(w0, 'w0', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (outside(t1, 0.0_dp, huge(1.0_dp), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't1 = '//real_str(t1) &
                           //': must be a finite number > 0 (s)')
            return
        end if
        call check_oscillator(period, 0.0_dp, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_finite_times(t, 't', stat, errmsg, ' (s)')
        if (stat /= SEISPULSE_SUCCESS) return
        om = two_pi / period
        ! sin(omega t1/2) = sin(pi t1/T) with exact argument reduction
        s1 = sin_pi(t1 / period)
        ! W0/omega^2 alone is never formed (it overflows for T > ~1e154 while z is finite):
        ! each sine is divided by omega first, a_abs = -omega^2 z is written without omega
        do i = 1, size(t)
            if (t(i) < 0.0_dp) cycle
            if (t(i) < t1) then
                ! z = -(W0/omega^2)(1 - cos omega t) = -2 W0 (sin(pi t/T)/omega)^2
                x = t(i) / period
                z(i) = -2.0_dp * w0 * (sin_pi(x) / om)**2
                v(i) = -w0 * (sin_pi(2.0_dp * x) / om)
                a_abs(i) = 2.0_dp * w0 * sin_pi(x)**2
            else
                ! Eq. 2.23: omega (t - t1/2) = 2 pi (t - t1/2)/T
                x = 2.0_dp * (t(i) - 0.5_dp * t1) / period
                z(i) = -2.0_dp * w0 * (s1 / om) * (sin_pi(x) / om)
                v(i) = -2.0_dp * w0 * (s1 / om) * cos_pi(x)
                a_abs(i) = 2.0_dp * w0 * s1 * sin_pi(x)
            end if
        end do
    end subroutine rect_pulse_response

    !> Dynamic coefficient of the rectangular pulse, max S/(m W0) = max |omega^2 z|/W0, undamped,
    !> against x = t1/T: BETA_PULSE_TEXTBOOK the book's 1 + 2 pi x (an additive upper bound: the
    !> peaks of W0 and omega J_W do not coincide); BETA_PULSE_EXACT 2 sin(pi x) for x <= 1/2,
    !> 2 beyond (doc/oscillator.md section 4).
    subroutine beta_pulse(t1_over_period, variant, beta, stat, errmsg)
        real(dp), intent(in) :: t1_over_period                !! t1/T, >= 0
        integer, intent(in) :: variant                        !! BETA_PULSE_TEXTBOOK or _EXACT
        real(dp), intent(out) :: beta                         !! dynamic coefficient
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        beta = 0.0_dp
        if (outside(t1_over_period, 0.0_dp, huge(1.0_dp), .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't1_over_period = ' &
                           //real_str(t1_over_period)//': must be a finite number >= 0')
            return
        end if
        stat = SEISPULSE_SUCCESS
        select case (variant)
        case (BETA_PULSE_TEXTBOOK)
            beta = 1.0_dp + two_pi * t1_over_period
        case (BETA_PULSE_EXACT)
            if (t1_over_period <= 0.5_dp) then
                beta = 2.0_dp * sin_pi(t1_over_period)
            else
                beta = 2.0_dp
            end if
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'variant = ' &
                           //int_str(variant)//': must be 1 (textbook) or 2 (exact)')
        end select
    end subroutine beta_pulse

    !> Largest |z| after an instantaneous acceleration impulse J_W (m/s) at t = 0, and its time:
    !> undamped |J_W|/omega at T/4 (Eq. 2.25); damped,
    !> z = -J_W e^(-zeta omega t) sin(omega_d t)/omega_d peaks at
    !> t* = atan2(sqrt(1 - zeta^2), zeta)/omega_d with |z| = (|J_W|/omega) e^(-zeta omega t*).
    subroutine impulse_max(jw, period, damping, z_max, t_max, stat, errmsg)
        real(dp), intent(in) :: jw                            !! J_W = W0 t1 (m/s)
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        real(dp), intent(out) :: z_max                        !! max |z| (m)
        real(dp), intent(out) :: t_max                        !! its first time (s)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(osc_t) :: osc
        real(dp) :: phi
        z_max = 0.0_dp
        t_max = 0.0_dp
        call check_amplitude(jw, 'jw', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_oscillator(period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        osc = make_osc(period, damping)
        ! Eq. 2.25 (max z = J_W/omega at t = T/4) when undamped; damped, the first
        ! stationary point of Eq. 2.24's damped form
        phi = atan2(osc%wd, damping)              ! omega_d t*; pi/2 when undamped
        t_max = phi / osc%wd / osc%omega
        z_max = abs(jw) / osc%omega * exp(-damping * phi / osc%wd)
    end subroutine impulse_max

    !> Response to an instantaneous acceleration impulse J_W (m/s) at t = 0 (the t1 -> 0 limit of
    !> the rectangle at fixed J_W = W0 t1; Eq. 2.24 when undamped): for t >= 0,
    !> z = -J_W e^(-zeta omega t) sin(omega_d t)/omega_d (z' = -J_W at t = 0+); zero for t < 0.
    subroutine impulse_response(t, jw, period, damping, z, v, a_abs, stat, errmsg)
        real(dp), intent(in) :: t(:)                          !! times (s), finite
        real(dp), intent(in) :: jw                            !! J_W (m/s)
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        real(dp), intent(out) :: z(:)                         !! relative displacement (m)
        real(dp), intent(out) :: v(:)                         !! relative velocity (m/s)
        real(dp), intent(out) :: a_abs(:)                     !! absolute acceleration (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(osc_t) :: osc
        complex(dp) :: w
        integer :: i
        call check_sizes(t, z, v, a_abs, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_amplitude(jw, 'jw', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_oscillator(period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_finite_times(t, 't', stat, errmsg, ' (s)')
        if (stat /= SEISPULSE_SUCCESS) return
        osc = make_osc(period, damping)
        do i = 1, size(t)
            if (t(i) < 0.0_dp) cycle
            ! a_g = J_W delta(t): K/omega = J_W e^(lambda sigma); undamped this is Eq. 2.24,
            ! z = -(J_W/omega) sin(omega t)
            w = cmplx(0.0_dp, jw / osc%wd, dp) * exp(osc%lam * (osc%omega * t(i)))
            call outputs(osc, w, z(i), v(i), a_abs(i))
        end do
    end subroutine impulse_response

    ! ==================================================================================
    ! Pulses of seispulse_pulses
    ! ==================================================================================

    !> Relative displacement, velocity and absolute acceleration of the oscillator under the
    !> pulse p, from rest, at arbitrary times (zero for t < 0 and before the pulse starts;
    !> the free vibration after it, evaluated analytically). Closed form for every kind but
    !> the Ricker wavelet (Gauss-Legendre quadrature to rounding level; see the module).
    subroutine sdof_pulse_response(p, period, damping, t, z, v, a_abs, stat, errmsg)
        type(pulse_t), intent(in) :: p                        !! the pulse (SI)
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        real(dp), intent(in) :: t(:)                          !! times (s), finite
        real(dp), intent(out) :: z(:)                         !! relative displacement (m)
        real(dp), intent(out) :: v(:)                         !! relative velocity (m/s)
        real(dp), intent(out) :: a_abs(:)                     !! absolute acceleration (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(model_t) :: m
        complex(dp) :: w
        integer :: i
        call check_sizes(t, z, v, a_abs, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_pulse_oscillator(p, period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_finite_times(t, 't', stat, errmsg, ' (s)')
        if (stat /= SEISPULSE_SUCCESS) return
        call build_model(p, period, damping, m)
        do i = 1, size(t)
            call model_state(m, t(i), w)
            call outputs(m%osc, w, z(i), v(i), a_abs(i))
        end do
    end subroutine sdof_pulse_response

    !> Maxima over all t >= 0 of |z| (m), |z'| (m/s) and |a_abs| (m/s^2) under the pulse p from
    !> rest, free vibration included, and the (earliest) times where they occur. Zero response
    !> (the spike, amp = 0): zero maxima at t = 0. The scan and refinement are described in
    !> the module documentation; a period too short for the scan (below 32/2^20 of the
    !> pulse's longest segment), an M&P pulse with gamma > 32767 or more than 32768 sine or
    !> cosine cycles is refused
    !> (SEISPULSE_INVALID_INPUT, the message names the shortest period allowed).
    subroutine sdof_pulse_peaks(p, period, damping, z_max, t_z, v_max, t_v, a_max, t_a, &
                                stat, errmsg)
        type(pulse_t), intent(in) :: p                        !! the pulse (SI)
        real(dp), intent(in) :: period                        !! natural period T (s), > 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        real(dp), intent(out) :: z_max                        !! max |z| (m)
        real(dp), intent(out) :: t_z                          !! time of max |z| (s)
        real(dp), intent(out) :: v_max                        !! max |z'| (m/s)
        real(dp), intent(out) :: t_v                          !! time of max |z'| (s)
        real(dp), intent(out) :: a_max                        !! max |a_abs| (m/s^2)
        real(dp), intent(out) :: t_a                          !! time of max |a_abs| (s)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(model_t) :: m
        real(dp) :: qmax(3), tmax(3)
        z_max = 0.0_dp
        t_z = 0.0_dp
        v_max = 0.0_dp
        t_v = 0.0_dp
        a_max = 0.0_dp
        t_a = 0.0_dp
        call check_pulse_oscillator(p, period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_scan_period(p, period, 'period', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call build_model(p, period, damping, m)
        call model_peaks(m, qmax, tmax)
        z_max = qmax(1)
        v_max = qmax(2)
        a_max = qmax(3)
        t_z = tmax(1)
        t_v = tmax(2)
        t_a = tmax(3)
    end subroutine sdof_pulse_peaks

    !> Response spectra of the pulse p (maxima over t >= 0, free vibration included, found as
    !> in sdof_pulse_peaks): sd = max|z| (m), sv = max|z'| (m/s), sa = max|a_abs| (m/s^2) for
    !> each period; period 0 gives sd = sv = 0 and sa = the peak |a_g| of the pulse (the rigid
    !> oscillator); for a pulse whose a_g jumps (rectangular, cosine_cycle, the box) the limit
    !> T -> 0+ of sa is larger (up to 2 PGA undamped; see the module). Positive periods below
    !> min_period, too short for the Ricker quadrature or for the peak scan are refused with a
    !> message naming periods(i). Optional: the times of the maxima.
    subroutine sdof_pulse_spectrum(p, periods, damping, sd, sv, sa, stat, errmsg, t_sd, t_sv, &
                                   t_sa)
        type(pulse_t), intent(in) :: p                        !! the pulse (SI)
        real(dp), intent(in) :: periods(:)                    !! natural periods T (s), >= 0
        real(dp), intent(in) :: damping                       !! damping ratio zeta (-), in [0, 1)
        real(dp), intent(out) :: sd(:)                        !! max |z| (m)
        real(dp), intent(out) :: sv(:)                        !! max |z'| (m/s)
        real(dp), intent(out) :: sa(:)                        !! max |a_abs| (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: t_sd(:)            !! times of max |z| (s)
        real(dp), intent(out), optional :: t_sv(:)            !! times of max |z'| (s)
        real(dp), intent(out), optional :: t_sa(:)            !! times of max |a_abs| (s)
        type(model_t) :: m
        real(dp) :: qmax(3), tmax(3), apk, tpk
        integer :: i, n
        n = size(periods)
        if (size(sd) /= n .or. size(sv) /= n .or. size(sa) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'sd, sv, sa: must have the length of periods')
            return
        end if
        call check_optional_size(t_sd, 't_sd', n, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_optional_size(t_sv, 't_sv', n, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_optional_size(t_sa, 't_sa', n, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        sd = 0.0_dp
        sv = 0.0_dp
        sa = 0.0_dp
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_damping(damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, n
            ! T = 0 (rigid) or min_period <= T finite: the check and bound of seispulse_sdof_sim
            call sdof_validate(periods(i), damping, stat, errmsg, &
                            period_name='periods('//int_str(i)//')')
            if (stat /= SEISPULSE_SUCCESS) return
            if (periods(i) > 0.0_dp) then
                call check_ricker_period(p, periods(i), 'periods('//int_str(i)//')', stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                call check_scan_period(p, periods(i), 'periods('//int_str(i)//')', stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
            end if
        end do
        call pulse_peak_accel(p, apk, tpk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 1, n
            if (periods(i) > 0.0_dp) then
                call build_model(p, periods(i), damping, m)
                call model_peaks(m, qmax, tmax)
            else
                ! a rigid oscillator moves with the ground: a_abs = a_g
                qmax = [0.0_dp, 0.0_dp, apk]
                tmax = [0.0_dp, 0.0_dp, tpk]
            end if
            sd(i) = qmax(1)
            sv(i) = qmax(2)
            sa(i) = qmax(3)
            if (present(t_sd)) t_sd(i) = tmax(1)
            if (present(t_sv)) t_sv(i) = tmax(2)
            if (present(t_sa)) t_sa(i) = tmax(3)
        end do
    end subroutine sdof_pulse_spectrum

    ! ==================================================================================
    ! Validation
    ! ==================================================================================

    !> The outputs z, v, a_abs must have the length of t; zeroed when they do.
    subroutine check_sizes(t, z, v, a, stat, errmsg)
        real(dp), intent(in) :: t(:)
        real(dp), intent(out) :: z(:), v(:), a(:)
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (size(z) /= size(t) .or. size(v) /= size(t) .or. size(a) /= size(t)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'z, v, a_abs: must have the length of t')
            return
        end if
        z = 0.0_dp
        v = 0.0_dp
        a = 0.0_dp
    end subroutine check_sizes

    subroutine check_amplitude(x, name, stat, errmsg)
        real(dp), intent(in) :: x
        character(len=*), intent(in) :: name
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. ieee_is_finite(x)) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
            name//' = '//real_str(x)//': must be a finite number')
    end subroutine check_amplitude

    subroutine check_damping(damping, stat, errmsg)
        real(dp), intent(in) :: damping
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        ! the same check and message as for records (seispulse_sdof_sim)
        call sdof_validate(0.0_dp, damping, stat, errmsg)
    end subroutine check_damping

    !> A positive period (finite, >= min_period of seispulse_sdof_sim, so that both modules accept
    !> the same periods and omega^2 stays finite) and a damping ratio in [0, 1).
    subroutine check_oscillator(period, damping, stat, errmsg)
        real(dp), intent(in) :: period, damping
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(period, min_period, huge(1.0_dp), .false., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'period = ' &
                           //real_str(period)//': must be a finite number >= ' &
                           //real_str(min_period)//' (s)')
            return
        end if
        call check_damping(damping, stat, errmsg)
    end subroutine check_oscillator

    !> r = theta/omega: finite, >= 0.
    subroutine check_ratio(ratio, stat, errmsg)
        real(dp), intent(in) :: ratio
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (outside(ratio, 0.0_dp, huge(1.0_dp), .false., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ratio = '//real_str(ratio) &
                           //': must be a finite number >= 0 (theta/omega)')
    end subroutine check_ratio

    !> 1 - r^2 as the product (1 - r)(1 + r): no cancellation near resonance (r = 1 gives 0).
    elemental function one_minus_r2(r) result(d)
        real(dp), intent(in) :: r
        real(dp) :: d
        d = (1.0_dp - r) * (1.0_dp + r)
    end function one_minus_r2

    !> An optional output array must have length n; zeroed when present.
    subroutine check_optional_size(x, name, n, stat, errmsg)
        real(dp), intent(out), optional :: x(:)
        character(len=*), intent(in) :: name
        integer, intent(in) :: n
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. present(x)) return
        if (size(x) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name &
                           //': must have the length of periods ('//int_str(n)//'), not ' &
                           //int_str(size(x)))
            return
        end if
        x = 0.0_dp
    end subroutine check_optional_size

    subroutine check_pulse_oscillator(p, period, damping, stat, errmsg)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period, damping
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_oscillator(period, damping, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_ricker_period(p, period, 'period', stat, errmsg)
    end subroutine check_pulse_oscillator

    !> The Ricker quadrature needs at most max_ricker_panels panels of min(T, 1/f_p)/32.
    subroutine check_ricker_period(p, period, name, stat, errmsg)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period
        character(len=*), intent(in) :: name     !! the period's name in the message
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: ts, te, tmin
        stat = SEISPULSE_SUCCESS
        if (p%kind /= PULSE_RICKER) return
        call ricker_window(p, ts, te)
        tmin = ricker_panels_per * (te - ts) / real(max_ricker_panels, dp)
        if (period < tmin) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//' = ' &
            //real_str(period)//': too short for the Ricker quadrature (must be >= ' &
            //real_str(tmin)//' s for this wavelet)')
    end subroutine check_ricker_period

    !> The peak scan takes at most max_scan steps per segment and at least scan_per_cycle per
    !> period of the oscillator and of each sinusoidal term: a longest segment d needs
    !> T >= scan_per_cycle d/max_scan (= d/32768), an M&P pulse gamma + 1 <= 32768 cycles
    !> (its fastest term has gamma + 1 cycles in the window), sine and cosine cycles
    !> n <= 32768. A coarser scan would alias.
    subroutine check_scan_period(p, period, name, stat, errmsg)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period
        character(len=*), intent(in) :: name     !! the period's name in the message
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: dmax, tmin
        stat = SEISPULSE_SUCCESS
        if (p%kind == PULSE_SINE_CYCLE .or. p%kind == PULSE_COSINE_CYCLE) then
            if (p%cycles > real(max_scan, dp) / scan_per_cycle) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'cycles = ' &
                    //real_str(p%cycles)//': too many cycles for the peak search (must be <= ' &
                    //real_str(real(max_scan, dp) / scan_per_cycle) &
                    //': at most 2^20 scan steps, 32 per cycle)')
                return
            end if
        end if
        if (p%kind == PULSE_MP) then
            if (p%gamma + 1.0_dp > real(max_scan, dp) / scan_per_cycle) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = ' &
                    //real_str(p%gamma)//': too many cycles for the peak search of an M&P ' &
                    //'pulse (must be <= '//real_str(real(max_scan, dp) / scan_per_cycle &
                    - 1.0_dp)//': at most 2^20 scan steps, 32 per cycle)')
                return
            end if
        end if
        dmax = longest_segment(p)
        tmin = scan_per_cycle * dmax / real(max_scan, dp)
        if (period < tmin) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//' = ' &
            //real_str(period)//': too short relative to the pulse for the peak search (its ' &
            //'longest segment, '//real_str(dmax)//' s, is scanned in at most 2^20 steps of ' &
            //'at most T/32; must be >= '//real_str(tmin)//' s for this pulse)')
    end subroutine check_scan_period

    !> Duration (s) of the longest closed-form segment of a valid pulse (0 for the Ricker
    !> wavelet, whose scan points are its quadrature panels, and for the spike). The segments
    !> do not depend on the oscillator.
    function longest_segment(p) result(dmax)
        type(pulse_t), intent(in) :: p
        real(dp) :: dmax
        type(model_t) :: m
        dmax = 0.0_dp
        if (p%kind == PULSE_RICKER) return
        call build_model(p, 1.0_dp, 0.0_dp, m)
        if (m%nseg > 0) dmax = maxval(m%seg(1:m%nseg)%dur)
    end function longest_segment

    ! ==================================================================================
    ! The model: segments, states, outputs
    ! ==================================================================================

    pure function make_osc(period, zeta) result(osc)
        real(dp), intent(in) :: period, zeta
        type(osc_t) :: osc
        osc%omega = two_pi / period
        osc%zeta = zeta
        osc%wd = sqrt((1.0_dp - zeta) * (1.0_dp + zeta))
        osc%lam = cmplx(-zeta, osc%wd, dp)
        osc%lam2 = osc%lam * osc%lam
        osc%lam3 = osc%lam2 * osc%lam
    end function make_osc

    !> e^(i x).
    elemental function phase(x) result(e)
        real(dp), intent(in) :: x
        complex(dp) :: e
        e = cmplx(cos(x), sin(x), dp)
    end function phase

    !> Physical outputs of the state V: z = Re V/omega (m), z' = Re(lambda V) (m/s),
    !> a_abs = omega Re(lambda^2 V) (m/s^2); with a_g (m/s^2) also their time derivatives:
    !> z', z'' = omega Re(lambda^2 V) - a_g, d a_abs/dt = omega (omega Re(lambda^3 V)
    !> + 2 zeta a_g).
    pure subroutine state_values(osc, w, q, ag, dq)
        type(osc_t), intent(in) :: osc
        complex(dp), intent(in) :: w
        real(dp), intent(out) :: q(3)                 !! z, z', a_abs
        real(dp), intent(in), optional :: ag          !! a_g at the same time
        real(dp), intent(out), optional :: dq(3)      !! d/dt of q (needs ag)
        real(dp) :: om
        om = osc%omega
        q(1) = real(w, dp) / om
        q(2) = real(osc%lam * w, dp)
        q(3) = real(osc%lam2 * w, dp) * om
        if (present(dq) .and. present(ag)) then
            dq(1) = q(2)
            dq(2) = q(3) - ag
            dq(3) = om * (real(osc%lam3 * w, dp) * om + 2.0_dp * osc%zeta * ag)
        end if
    end subroutine state_values

    !> z, z', a_abs of the state V (state_values, one point).
    pure subroutine outputs(osc, w, z, v, a)
        type(osc_t), intent(in) :: osc
        complex(dp), intent(in) :: w
        real(dp), intent(out) :: z, v, a
        real(dp) :: q(3)
        call state_values(osc, w, q)
        z = q(1)
        v = q(2)
        a = q(3)
    end subroutine outputs

    !> State W and a_g at fraction s of a segment.
    pure subroutine seg_state(osc, seg, p, s, w, ag)
        type(osc_t), intent(in) :: osc
        type(seg_t), intent(in) :: seg
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: s
        complex(dp), intent(out) :: w
        real(dp), intent(out) :: ag
        complex(dp) :: x0, k, e, ey, kcos, ksin
        real(dp) :: sigma, tau
        integer :: i
        sigma = seg%len * s
        tau = seg%dur * s
        x0 = osc%lam * sigma
        k = (0.0_dp, 0.0_dp)
        if (seg%quad) then
            call ricker_kernel(osc, seg, p, sigma, tau, k)
        else
            do i = 1, seg%nexp
                ! C e^(M (s - v)) -> C tau e[lambda sigma - M v, M (s - v)]
                call cexp_dd1(x0 - seg%me(i) * seg%ve(i), &
                         cmplx(seg%me(i) * (s - seg%ve(i)), 0.0_dp, dp), e, ey)
                k = k + seg%ce(i) * e
            end do
            do i = 1, seg%nsin
                ! Re(C e^(i kappa s)) = Cr cos(kappa s) - Ci sin(kappa s)
                call sin_kernels(x0, seg%ks(i) * s, kcos, ksin, ey)
                k = k + real(seg%cs(i), dp) * kcos - aimag(seg%cs(i)) * ksin
            end do
            k = k * tau
            ! C s phi_1(R s) -> C tau s e[lambda sigma, R s, 0]
            if (seg%has_r) k = k + seg%cr * tau * s * cexp_dd2(x0, cmplx(seg%rr * s, 0.0_dp, dp), &
                                                               (0.0_dp, 0.0_dp))
        end if
        ag = seg_accel(p, seg, s)
        w = exp(x0) * seg%wa
        if (seg%quad .or. .not. (osc%wd * sigma < 1.0_dp)) then
            w = w + cmplx(0.0_dp, 1.0_dp / osc%wd, dp) * k
        else
            ! Re V = -Im(K/omega)/sqrt(1 - zeta^2) would keep only ~omega_d t of the digits
            ! of K (relative error eps/(omega_d t): long periods, the start of a segment,
            ! zeta -> 1); with the impulse response sigma e[lambda sigma, conj(lambda) sigma]
            ! it is a divided difference over the conjugate pair, with no cancellation.
            ! (Ricker: each quadrature node's Im e^(lambda v) = e^(-zeta v) sin(omega_d v) is
            ! accurate as it stands.)
            w = w + cmplx(forced_real(seg, s, sigma, tau, x0), &
                          real(k, dp) / osc%wd, dp)
        end if
    end subroutine seg_state

    !> omega z of the forced part at fraction s (from rest at the segment start), for
    !> omega_d t < 1: each term C e^(y s) contributes -C tau sigma e[x, conj(x), y s]
    !> (x = lambda sigma, shifted for referenced exponentials), the expm1 ramp
    !> -C tau sigma s e[x, conj(x), R s, 0].
    pure function forced_real(seg, s, sigma, tau, x0) result(zr)
        type(seg_t), intent(in) :: seg
        real(dp), intent(in) :: s, sigma, tau
        complex(dp), intent(in) :: x0
        real(dp) :: zr
        complex(dp) :: sh
        integer :: i
        zr = 0.0_dp
        do i = 1, seg%nexp
            sh = cmplx(seg%me(i) * seg%ve(i), 0.0_dp, dp)
            zr = zr - seg%ce(i) * real(cexp_dd2(x0 - sh, conjg(x0) - sh, &
                                                cmplx(seg%me(i) * (s - seg%ve(i)), 0.0_dp, dp)), dp)
        end do
        do i = 1, seg%nsin
            zr = zr - real(seg%cs(i) * cexp_dd2(x0, conjg(x0), &
                                                cmplx(0.0_dp, seg%ks(i) * s, dp)), dp)
        end do
        zr = zr * (tau * sigma)
        if (seg%has_r) zr = zr - seg%cr * (tau * sigma) * s &
            * real(cexp_dd3(x0, conjg(x0), cmplx(seg%rr * s, 0.0_dp, dp), (0.0_dp, 0.0_dp)), dp)
    end function forced_real

    !> Kernels of cos(kappa s) and sin(kappa s) over [0, s] divided by sigma:
    !> (e1 + e2)/2 and (e1 - e2)/(2i) with e1,2 = e[x, +-i ks]; for |ks| < 1 the difference is
    !> ks e[x, i ks, -i ks] (no cancellation). ey = e^(i ks).
    pure subroutine sin_kernels(x, ks, kcos, ksin, ey)
        complex(dp), intent(in) :: x
        real(dp), intent(in) :: ks
        complex(dp), intent(out) :: kcos, ksin, ey
        complex(dp) :: y, e, e2, ey2, d
        y = cmplx(0.0_dp, ks, dp)
        call cexp_dd1(x, y, e, ey)
        if (abs(ks) < 1.0_dp) then
            d = cexp_dd2(x, y, conjg(y))
            ksin = ks * d
            kcos = e - cmplx(0.0_dp, ks, dp) * d
        else
            call cexp_dd1(x, conjg(y), e2, ey2)
            kcos = 0.5_dp * (e + e2)
            ksin = cmplx(0.0_dp, -0.5_dp, dp) * (e - e2)
        end if
    end subroutine sin_kernels

    !> Ground acceleration at fraction s of a segment (closed form or Ricker).
    pure function seg_accel(p, seg, s) result(ag)
        type(pulse_t), intent(in) :: p
        type(seg_t), intent(in) :: seg
        real(dp), intent(in) :: s
        real(dp) :: ag, p1, p2, p3
        integer :: i
        if (seg%quad) then
            ag = ricker_accel(p, seg%ta + s * seg%dur)
            return
        end if
        ag = 0.0_dp
        do i = 1, seg%nexp
            ag = ag + seg%ce(i) * exp(seg%me(i) * (s - seg%ve(i)))
        end do
        do i = 1, seg%nsin
            ag = ag + real(seg%cs(i) * cmplx(cos(seg%ks(i) * s), sin(seg%ks(i) * s), dp), dp)
        end do
        if (seg%has_r) then
            call exp_phis(seg%rr * s, p1, p2, p3)
            ag = ag + seg%cr * s * p1
        end if
    end function seg_accel

    !> Advance V from s0 to s1 in a closed-form segment by one step of the exact
    !> recurrence V1 = e^(lambda h L) V0 + (i/sqrt(1 - zeta^2)) dK/omega, with the kernel
    !> constants of
    !> the step length cached in st (used by the scan only: rounding accumulates linearly
    !> with the number of steps, so every value that can become a result is re-evaluated
    !> directly). ag1 = a_g(s1).
    pure subroutine step_state(osc, seg, st, s0, s1, w, ag1)
        type(osc_t), intent(in) :: osc
        type(seg_t), intent(in) :: seg
        type(step_t), intent(inout) :: st
        real(dp), intent(in) :: s0, s1
        complex(dp), intent(inout) :: w
        real(dp), intent(out) :: ag1
        complex(dp) :: x, k, e, ey, cj
        real(dp) :: h, hs, ht, top, p1, p2, p3
        integer :: i
        h = s1 - s0
        hs = seg%len * h
        ht = seg%dur * h
        x = osc%lam * hs
        if (abs(h - st%h) > 1.0e-13_dp * h) then
            st%h = h
            st%eh = exp(x)
            do i = 1, seg%nexp
                if (abs(seg%me(i) * h) <= 40.0_dp) then
                    call cexp_dd1(x, cmplx(seg%me(i) * h, 0.0_dp, dp), e, ey)
                    st%kexp(i) = ht * e
                end if
            end do
            do i = 1, seg%nsin
                call sin_kernels(x, seg%ks(i) * h, st%kcos(i), st%ksin(i), ey)
                st%kcos(i) = ht * st%kcos(i)
                st%ksin(i) = ht * st%ksin(i)
            end do
            if (seg%has_r) then
                st%kra = ht * h * cexp_dd2(x, cmplx(seg%rr * h, 0.0_dp, dp), (0.0_dp, 0.0_dp))
                st%krb = ht * phi1(x)
            end if
        end if
        k = (0.0_dp, 0.0_dp)
        do i = 1, seg%nexp
            ! C e^(M (s0 - v)) e^(M w) on the step; its largest value is at one end
            top = seg%me(i) * (merge(s1, s0, seg%me(i) > 0.0_dp) - seg%ve(i))
            if (top < -700.0_dp) cycle
            if (abs(seg%me(i) * h) <= 40.0_dp) then
                k = k + seg%ce(i) * exp(seg%me(i) * (s0 - seg%ve(i))) * st%kexp(i)
            else
                call cexp_dd1(x + seg%me(i) * (s0 - seg%ve(i)), &
                         cmplx(seg%me(i) * (s1 - seg%ve(i)), 0.0_dp, dp), e, ey)
                k = k + seg%ce(i) * ht * e
            end if
        end do
        do i = 1, seg%nsin
            cj = seg%cs(i) * cmplx(cos(seg%ks(i) * s0), sin(seg%ks(i) * s0), dp)
            k = k + real(cj, dp) * st%kcos(i) - aimag(cj) * st%ksin(i)
        end do
        if (seg%has_r) then
            ! C (e^(R s) - 1)/R = C [e^(R s0) w phi_1(R w) + s0 phi_1(R s0)], w = s - s0
            call exp_phis(seg%rr * s0, p1, p2, p3)
            k = k + seg%cr * (exp(seg%rr * s0) * st%kra + s0 * p1 * st%krb)
        end if
        w = st%eh * w + cmplx(0.0_dp, 1.0_dp / osc%wd, dp) * k
        ag1 = seg_accel(pulse_t(), seg, s1)
    end subroutine step_state

    !> Segment k of the model (a Ricker panel is made on the fly).
    pure function get_seg(m, k) result(seg)
        type(model_t), intent(in) :: m
        integer, intent(in) :: k
        type(seg_t) :: seg
        if (m%ricker) then
            seg%ta = m%ts + real(k - 1, dp) * m%hp
            seg%dur = m%hp
            seg%len = m%osc%omega * m%hp
            seg%quad = .true.
            seg%hmax = 1.0_dp
            seg%wa = m%wp(k - 1)
        else
            seg = m%seg(k)
        end if
    end function get_seg

    !> State at the end of segment k.
    pure function seg_end_state(m, k) result(w)
        type(model_t), intent(in) :: m
        integer, intent(in) :: k
        complex(dp) :: w
        if (m%ricker) then
            w = m%wp(k)
        else if (k < m%nseg) then
            w = m%seg(k + 1)%wa
        else
            w = m%w_end
        end if
    end function seg_end_state

    !> Ricker panel: K/omega by 20-point Gauss-Legendre on [0, tau].
    pure subroutine ricker_kernel(osc, seg, p, sigma, tau, k)
        type(osc_t), intent(in) :: osc
        type(seg_t), intent(in) :: seg
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: sigma, tau
        complex(dp), intent(out) :: k
        complex(dp) :: kp(10), km(10)
        k = (0.0_dp, 0.0_dp)
        if (.not. (sigma > 0.0_dp)) return
        call gl_weights(osc, sigma, tau, kp, km)
        k = gl_panel(p, seg%ta + 0.5_dp * tau, tau, kp, km)
    end subroutine ricker_kernel

    !> Weights of the 20-point Gauss-Legendre rule for K/omega = int_0^tau e^(lambda omega
    !> (tau - u)) a_g(ta + u) du on one panel (phase length sig = omega tau): nodes
    !> u = (tau/2)(1 +- x_j), so sigma - omega u = (sig/2)(1 -+ x_j).
    pure subroutine gl_weights(osc, sig, tau, kp, km)
        type(osc_t), intent(in) :: osc
        real(dp), intent(in) :: sig, tau
        complex(dp), intent(out) :: kp(10), km(10)   !! weights of the nodes right, left of mid
        kp = (0.5_dp * tau) * gl_w * exp(osc%lam * ((0.5_dp * sig) * (1.0_dp - gl_x)))
        km = (0.5_dp * tau) * gl_w * exp(osc%lam * ((0.5_dp * sig) * (1.0_dp + gl_x)))
    end subroutine gl_weights

    !> K/omega of the Ricker panel centred at tmid, of duration tau, with gl_weights' weights.
    pure function gl_panel(p, tmid, tau, kp, km) result(k)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: tmid, tau
        complex(dp), intent(in) :: kp(10), km(10)
        complex(dp) :: k
        k = sum(kp * ricker_accel(p, tmid + (0.5_dp * tau) * gl_x) &
                + km * ricker_accel(p, tmid - (0.5_dp * tau) * gl_x))
    end function gl_panel

    !> Append a segment [ta, ta + dur] (dur > 0).
    subroutine add_seg(m, ta, dur)
        type(model_t), intent(inout) :: m
        real(dp), intent(in) :: ta, dur
        type(seg_t), allocatable :: tmp(:)
        if (.not. allocated(m%seg)) allocate(m%seg(8))
        if (m%nseg == size(m%seg)) then
            allocate(tmp(2 * size(m%seg)))
            tmp(1:m%nseg) = m%seg(1:m%nseg)
            call move_alloc(tmp, m%seg)
        end if
        m%nseg = m%nseg + 1
        m%seg(m%nseg) = seg_t()
        m%seg(m%nseg)%ta = ta
        m%seg(m%nseg)%dur = dur
        m%seg(m%nseg)%len = m%osc%omega * dur
    end subroutine add_seg

    pure subroutine add_exp(seg, c, mexp, vref)
        type(seg_t), intent(inout) :: seg
        real(dp), intent(in) :: c, mexp, vref
        seg%nexp = seg%nexp + 1
        seg%ce(seg%nexp) = c
        seg%me(seg%nexp) = mexp
        seg%ve(seg%nexp) = vref
    end subroutine add_exp

    pure subroutine add_sin(seg, c, kappa)
        type(seg_t), intent(inout) :: seg
        complex(dp), intent(in) :: c
        real(dp), intent(in) :: kappa
        seg%nsin = seg%nsin + 1
        seg%cs(seg%nsin) = c
        seg%ks(seg%nsin) = kappa
    end subroutine add_sin

    !> Segments and terms of a valid pulse, and the states at the segment starts.
    subroutine build_model(p, period, zeta, m)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: period, zeta
        type(model_t), intent(out) :: m
        real(dp) :: a, td, r, ts, te, h, gam, kk(3), ww(3), q(3), nu, tmid
        complex(dp) :: w, eh, kern, kplus(10), kminus(10)
        real(dp) :: ag
        integer :: lobe, k, n
        m%osc = make_osc(period, zeta)
        m%p = p
        m%nseg = 0
        a = p%amp
        td = p%duration
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            do lobe = 1, merge(2, 1, p%full)
                ! second lobe: the first negated and shifted by t_d
                call add_exp_lobe(m, real(lobe - 1, dp) * td, td, merge(a, -a, lobe == 1), p%beta)
            end do
        case (PULSE_HALF_SINE)
            call add_seg(m, 0.0_dp, td)
            call add_sin(m%seg(1), cmplx(0.0_dp, -a, dp), pi)           ! A sin(pi s)
        case (PULSE_SINE_CYCLE)
            ! n cycles: one segment of n T, A sin(2 pi n s) (exact: the same a_g, no
            ! superposition error; n = 1 is the single cycle)
            call add_seg(m, 0.0_dp, td * p%cycles)
            call add_sin(m%seg(1), cmplx(0.0_dp, -a, dp), two_pi * p%cycles)   ! A sin(2 pi n s)
        case (PULSE_COSINE_CYCLE)
            call add_seg(m, 0.0_dp, td * p%cycles)
            call add_sin(m%seg(1), cmplx(a, 0.0_dp, dp), two_pi * p%cycles)    ! A cos(2 pi n s)
        case (PULSE_RECTANGULAR)
            call add_seg(m, 0.0_dp, td)
            call add_exp(m%seg(1), a, 0.0_dp, 0.0_dp)
        case (PULSE_TRIANGULAR)
            r = p%peak_frac
            if (r * td > 0.0_dp) then
                call add_seg(m, 0.0_dp, r * td)
                m%seg(m%nseg)%has_r = .true.          ! A s
                m%seg(m%nseg)%cr = a
            end if
            if (r < 1.0_dp) then
                call add_seg(m, r * td, td - r * td)
                call add_exp(m%seg(m%nseg), a, 0.0_dp, 0.0_dp)
                m%seg(m%nseg)%has_r = .true.          ! A (1 - s)
                m%seg(m%nseg)%cr = -a
            end if
        case (PULSE_RICKER)
            ! equal panels of at most min(T, 1/f_p)/32, 20-point Gauss-Legendre on each; the
            ! kernel weights are the same for every panel
            call ricker_window(p, ts, te)
            h = min(period, 1.0_dp / p%freq) / ricker_panels_per
            n = max(1, ceiling((te - ts) / h))
            h = (te - ts) / real(n, dp)
            m%ricker = .true.
            m%nseg = n
            m%ts = ts
            m%hp = h
            allocate(m%wp(0:n))
            call gl_weights(m%osc, m%osc%omega * h, h, kplus, kminus)
            eh = exp(m%osc%lam * (m%osc%omega * h))
            w = (0.0_dp, 0.0_dp)
            m%wp(0) = w
            do k = 1, n
                tmid = ts + (real(k, dp) - 0.5_dp) * h
                kern = gl_panel(p, tmid, h, kplus, kminus)
                w = eh * w + cmplx(0.0_dp, 1.0_dp / m%osc%wd, dp) * kern
                m%wp(k) = w
            end do
            m%w_end = w
            m%t_end = ts + real(n, dp) * h
            return
        case (PULSE_MP)
            ! a = A f sum_j w_j (-k_j) sin(k_j x + nu), x = f (t - t0) = -gam/2 + gam s,
            ! k = 2 pi (1, 1 + 1/gam, 1 - 1/gam), w = (1/2, 1/4, 1/4):
            ! -k sin(k x + nu) = Re(i k e^(i (nu - k gam/2)) e^(i k gam s))
            gam = p%gamma
            nu = p%nu_deg * (pi / 180.0_dp)
            call mp_terms(gam, kk, ww)
            q = [gam, gam + 1.0_dp, gam - 1.0_dp]      ! k gam/2 = pi q
            call add_seg(m, p%t0 - 0.5_dp * gam / p%freq, gam / p%freq)
            do k = 1, 3
                call add_sin(m%seg(1), a * p%freq * ww(k) * cmplx(0.0_dp, kk(k), dp) &
                             * cmplx(cos(nu), sin(nu), dp) &
                             * cmplx(cos_pi(q(k)), -sin_pi(q(k)), dp), &
                             kk(k) * gam)
            end do
        end select
        ! carry the state across the segments
        w = (0.0_dp, 0.0_dp)
        do k = 1, m%nseg
            m%seg(k)%wa = w
            call seg_state(m%osc, m%seg(k), p, 1.0_dp, w, ag)
        end do
        m%w_end = w
        if (m%nseg > 0) then
            m%t_end = m%seg(m%nseg)%ta + m%seg(m%nseg)%dur
        else
            m%t_end = 0.0_dp
        end if
    end subroutine build_model

    !> One lobe of the exponential pulse (amplitude a, possibly negated) from t0: a rising
    !> and a falling half of t_d/2 each (doc/pulses.md Eq. 1.1b), in forms without overflow for
    !> every beta and with terms bounded by a few |A| (they cancel only where a_g -> 0 at a
    !> half lobe's zero end: absolute accuracy there; see the module documentation).
    subroutine add_exp_lobe(m, t0, td, a, beta)
        type(model_t), intent(inout) :: m
        real(dp), intent(in) :: t0, td, a, beta
        real(dp) :: p1, p2, p3, c, em
        integer :: k
        if (beta > huge(beta)) return                ! the spike: no area, no response
        if (beta < -huge(beta)) then                 ! the box
            call add_seg(m, t0, td)
            call add_exp(m%seg(m%nseg), a, 0.0_dp, 0.0_dp)
            return
        end if
        call add_seg(m, t0, 0.5_dp * td)
        k = m%nseg
        if (abs(beta) <= beta_small) then
            ! a = A s phi_1(beta s)/phi_1(beta)  (= A s for the triangle)
            call exp_phis(beta, p1, p2, p3)
            m%seg(k)%has_r = .true.
            m%seg(k)%rr = beta
            m%seg(k)%cr = a / p1
        else if (beta > 0.0_dp) then
            ! a = A [e^(beta (s - 1)) - e^-beta]/(1 - e^-beta): referenced at the peak
            c = a / (-expm1(-beta))
            call add_exp(m%seg(k), c, beta, 1.0_dp)
            call add_exp(m%seg(k), -c * exp(-beta), 0.0_dp, 0.0_dp)
            m%seg(k)%grade = beta
            m%seg(k)%sharp = 2
        else
            ! a = A [1 - e^(beta s)]/(1 - e^beta): referenced at the start
            c = a / (-expm1(beta))
            call add_exp(m%seg(k), c, 0.0_dp, 0.0_dp)
            call add_exp(m%seg(k), -c, beta, 0.0_dp)
            m%seg(k)%grade = -beta
            m%seg(k)%sharp = 1
        end if
        call add_seg(m, t0 + 0.5_dp * td, 0.5_dp * td)
        k = m%nseg
        if (abs(beta) <= beta_small) then
            ! a(s) = rise(1 - s) = A [1 - e^beta s phi_1(-beta s)/phi_1(beta)]
            call exp_phis(beta, p1, p2, p3)
            em = exp(beta)
            call add_exp(m%seg(k), a, 0.0_dp, 0.0_dp)
            m%seg(k)%has_r = .true.
            m%seg(k)%rr = -beta
            m%seg(k)%cr = -a * em / p1
        else if (beta > 0.0_dp) then
            ! a = A [e^(-beta s) - e^-beta]/(1 - e^-beta)
            c = a / (-expm1(-beta))
            call add_exp(m%seg(k), c, -beta, 0.0_dp)
            call add_exp(m%seg(k), -c * exp(-beta), 0.0_dp, 0.0_dp)
            m%seg(k)%grade = beta
            m%seg(k)%sharp = 1
        else
            ! a = A [1 - e^(beta (1 - s))]/(1 - e^beta): referenced at the end
            c = a / (-expm1(beta))
            call add_exp(m%seg(k), c, 0.0_dp, 0.0_dp)
            call add_exp(m%seg(k), -c, -beta, 1.0_dp)
            m%seg(k)%grade = -beta
            m%seg(k)%sharp = 2
        end if
    end subroutine add_exp_lobe

    !> State W at time t (zero before the pulse, free vibration after it).
    subroutine model_state(m, t, w)
        type(model_t), intent(in) :: m
        real(dp), intent(in) :: t
        complex(dp), intent(out) :: w
        type(seg_t) :: seg
        real(dp) :: ag, s
        integer :: lo, hi, mid
        w = (0.0_dp, 0.0_dp)
        if (m%nseg == 0 .or. t < 0.0_dp) return
        seg = get_seg(m, 1)
        if (t < seg%ta) return
        if (t >= m%t_end) then
            w = m%w_end * exp(m%osc%lam * (m%osc%omega * (t - m%t_end)))
            return
        end if
        if (m%ricker) then
            lo = min(m%nseg, max(1, int((t - m%ts) / m%hp) + 1))
        else
            ! last segment with ta <= t
            lo = 1
            hi = m%nseg
            do while (hi > lo)
                mid = (lo + hi + 1) / 2
                if (m%seg(mid)%ta <= t) then
                    lo = mid
                else
                    hi = mid - 1
                end if
            end do
        end if
        seg = get_seg(m, lo)
        s = min(1.0_dp, max(0.0_dp, (t - seg%ta) / seg%dur))
        call seg_state(m%osc, seg, m%p, s, w, ag)
    end subroutine model_state

    ! ==================================================================================
    ! Peaks
    ! ==================================================================================

    !> z, z', a_abs and their time derivatives at fraction s of a segment.
    pure subroutine point_values(osc, seg, p, s, q, dq)
        type(osc_t), intent(in) :: osc
        type(seg_t), intent(in) :: seg
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: s
        real(dp), intent(out) :: q(3), dq(3)
        complex(dp) :: w
        real(dp) :: ag
        call seg_state(osc, seg, p, s, w, ag)
        call state_values(osc, w, q, ag, dq)
    end subroutine point_values

    !> Keep the largest |q|; among values equal to rounding, the earliest time.
    pure subroutine update(best, tbest, q, t)
        real(dp), intent(inout) :: best, tbest
        real(dp), intent(in) :: q, t
        real(dp), parameter :: tie = 1.0e-13_dp
        if (abs(q) > best * (1.0_dp + tie)) then
            best = abs(q)
            tbest = t
        else if (abs(q) >= best * (1.0_dp - tie) .and. t < tbest) then
            best = max(best, abs(q))
            tbest = t
        end if
    end subroutine update

    !> Maxima of |z|, |z'|, |a_abs| and their times (module documentation: scan, brackets,
    !> refinement). Scan values inside a segment come from the one-step recurrence and only
    !> steer the search; segment ends, roots and the best interior sample are evaluated
    !> directly.
    subroutine model_peaks(m, qmax, tmax)
        type(model_t), intent(in) :: m
        real(dp), intent(out) :: qmax(3), tmax(3)
        real(dp), allocatable :: s(:)
        type(bracket_t), allocatable :: br(:), tmp(:)
        type(seg_t) :: seg
        type(step_t) :: st
        type(slope_fn) :: f
        real(dp) :: q(3), dq(3), q0(3), dq0(3), t, est, x, qr(3), dqr(3), ag, samp(3), samp_s(3)
        complex(dp) :: w
        integer :: samp_k(3), k, j, i, n, nbr, stat
        qmax = 0.0_dp
        tmax = huge(1.0_dp)
        q0 = 0.0_dp
        dq0 = 0.0_dp
        samp = -1.0_dp
        samp_s = 0.0_dp
        samp_k = 0
        if (m%nseg == 0) then
            tmax = 0.0_dp
            return
        end if
        allocate(br(64))
        nbr = 0
        ! pass 1: scan every segment, bracket the stationary points
        do k = 1, m%nseg
            seg = get_seg(m, k)
            if (seg%quad) then
                n = 1
                if (.not. allocated(s)) allocate(s(0:1))
                s(0:1) = [0.0_dp, 1.0_dp]
            else
                call scan_points(seg, s, n)
            end if
            st%h = -1.0_dp
            w = seg%wa
            do j = 0, n
                if (j == 0) then
                    ag = seg_accel(m%p, seg, 0.0_dp)
                else if (j == n) then
                    w = seg_end_state(m, k)
                    ag = seg_accel(m%p, seg, 1.0_dp)
                else
                    call step_state(m%osc, seg, st, s(j - 1), s(j), w, ag)
                end if
                call state_values(m%osc, w, q, ag, dq)
                dq = seg%dur * dq          ! slopes d/ds
                t = seg%ta + s(j) * seg%dur
                do i = 1, 3
                    if (j == 0 .or. j == n) then
                        call update(qmax(i), tmax(i), q(i), t)
                    else if (abs(q(i)) > samp(i)) then
                        samp(i) = abs(q(i))
                        samp_k(i) = k
                        samp_s(i) = s(j)
                    end if
                    if (j == 0) cycle
                    if ((dq0(i) > 0.0_dp .and. dq(i) < 0.0_dp) .or. &
                        (dq0(i) < 0.0_dp .and. dq(i) > 0.0_dp)) then
                        est = hermite_extremum(q0(i), dq0(i), q(i), dq(i), s(j) - s(j - 1))
                        if (nbr == size(br)) then
                            allocate(tmp(2 * nbr))
                            tmp(1:nbr) = br(1:nbr)
                            call move_alloc(tmp, br)
                        end if
                        nbr = nbr + 1
                        br(nbr) = bracket_t(k, i, s(j - 1), s(j), est)
                    end if
                end do
                q0 = q
                dq0 = dq
            end do
        end do
        call free_peaks(m, qmax, tmax)
        ! the best interior sample, directly (a lower bound even if its bracket were missed)
        do i = 1, 3
            if (samp_k(i) == 0) cycle
            seg = get_seg(m, samp_k(i))
            call point_values(m%osc, seg, m%p, samp_s(i), qr, dqr)
            call update(qmax(i), tmax(i), qr(i), seg%ta + samp_s(i) * seg%dur)
        end do
        ! pass 2: refine the brackets that may hold the maximum
        f%osc = m%osc
        f%p = m%p
        do j = 1, nbr
            i = br(j)%which
            if (br(j)%est < qmax(i) * (1.0_dp - prune_margin)) cycle
            k = br(j)%seg
            f%seg = get_seg(m, k)
            f%which = i
            call find_root(f, br(j)%sa, br(j)%sb, x, stat, max_iter=200)
            if (stat /= SEISPULSE_SUCCESS) cycle
            call point_values(m%osc, f%seg, m%p, x, qr, dqr)
            call update(qmax(i), tmax(i), qr(i), f%seg%ta + x * f%seg%dur)
        end do
        do i = 1, 3
            if (.not. (qmax(i) > 0.0_dp)) tmax(i) = 0.0_dp
        end do
    end subroutine model_peaks

    !> After the pulse, q = Re(kappa V_end e^(lambda sigma)) is a damped sinusoid: its largest
    !> |q| on [t_end, inf) is at t_end (a scan point already) or at its first stationary point,
    !> sqrt(1 - zeta^2) sigma + arg(lambda kappa V_end) = pi/2 (mod pi).
    subroutine free_peaks(m, qmax, tmax)
        type(model_t), intent(in) :: m
        real(dp), intent(inout) :: qmax(3), tmax(3)
        complex(dp) :: kap(3), g, w
        real(dp) :: sig, scale(3)
        integer :: i
        if (.not. (abs(m%w_end) > 0.0_dp)) return
        kap = [(1.0_dp, 0.0_dp), m%osc%lam, m%osc%lam2]
        scale = [1.0_dp / m%osc%omega, 1.0_dp, m%osc%omega]
        do i = 1, 3
            g = m%osc%lam * kap(i) * m%w_end
            if (.not. (abs(g) > 0.0_dp)) cycle
            sig = modulo(0.5_dp * pi - atan2(aimag(g), real(g, dp)), pi) / m%osc%wd
            w = kap(i) * m%w_end * exp(m%osc%lam * sig)
            call update(qmax(i), tmax(i), scale(i) * real(w, dp), m%t_end + sig / m%osc%omega)
        end do
    end subroutine free_peaks

    !> Extreme value of the cubic Hermite interpolant of (q, dq/ds) on a step of length h
    !> whose slopes have opposite signs (one stationary point inside, found by bisection).
    pure function hermite_extremum(qa, da, qb, db, h) result(est)
        real(dp), intent(in) :: qa, da, qb, db, h
        real(dp) :: est, a2, a1, a0, lo, hi, mid, th, fl, fm
        integer :: it
        ! H'(th)/1 = a2 th^2 + a1 th + a0
        a2 = 6.0_dp * (qa - qb) + 3.0_dp * h * (da + db)
        a1 = 6.0_dp * (qb - qa) - h * (4.0_dp * da + 2.0_dp * db)
        a0 = h * da
        lo = 0.0_dp
        hi = 1.0_dp
        fl = a0
        do it = 1, 50
            mid = 0.5_dp * (lo + hi)
            fm = (a2 * mid + a1) * mid + a0
            if ((fm > 0.0_dp .and. fl > 0.0_dp) .or. (fm < 0.0_dp .and. fl < 0.0_dp)) then
                lo = mid
                fl = fm
            else
                hi = mid
            end if
        end do
        th = 0.5_dp * (lo + hi)
        est = abs(qa * (1.0_dp + 2.0_dp * th) * (1.0_dp - th)**2 + h * da * th * (1.0_dp - th)**2 &
                  + qb * th * th * (3.0_dp - 2.0_dp * th) - h * db * th * th * (1.0_dp - th))
    end function hermite_extremum

    !> Scan fractions s(0:n) of a segment (module documentation: step limits and grading).
    subroutine scan_points(seg, s, n)
        type(seg_t), intent(in) :: seg
        real(dp), allocatable, intent(inout) :: s(:)
        integer, intent(out) :: n
        real(dp) :: h, h0, hk, d
        integer :: i, j
        h = seg%hmax
        if (seg%len > 0.0_dp) h = min(h, two_pi / seg%len / scan_per_cycle)
        do i = 1, seg%nsin
            if (abs(seg%ks(i)) > 0.0_dp) h = min(h, two_pi / abs(seg%ks(i)) / scan_per_cycle)
        end do
        ! never reached for accepted input (check_scan_period refuses the periods and M&P
        ! pulses that would need more steps); a guard on the step count only
        h = max(h, 1.0_dp / real(max_scan, dp))
        h0 = h
        if (seg%grade > 0.0_dp) h0 = max(0.25_dp / seg%grade, grade_floor)
        if (h0 < h) then
            ! graded from the sharp end: steps h0, 1.25 h0, ... up to h
            n = 0
            d = 0.0_dp
            hk = h0
            do while (d < 1.0_dp)
                d = d + min(hk, h)
                hk = hk * grade_factor
                n = n + 1
            end do
            call ensure(s, n)
            s(0) = 0.0_dp
            hk = h0
            do j = 1, n - 1
                s(j) = s(j - 1) + min(hk, h)
                hk = hk * grade_factor
            end do
            s(n) = 1.0_dp
            if (seg%sharp == 2) s(0:n) = 1.0_dp - s(n:0:-1)
        else
            n = max(1, ceiling(1.0_dp / h - 1.0e-9_dp))
            call ensure(s, n)
            do j = 0, n
                s(j) = real(j, dp) / real(n, dp)
            end do
        end if
    contains
        subroutine ensure(buf, nn)
            real(dp), allocatable, intent(inout) :: buf(:)
            integer, intent(in) :: nn
            if (allocated(buf)) then
                if (ubound(buf, 1) >= nn) return
                deallocate(buf)
            end if
            allocate(buf(0:nn))
        end subroutine ensure
    end subroutine scan_points

    !> d/dt of z, z' or a_abs (self%which) at fraction x of the segment.
    function slope_eval(self, x) result(y)
        class(slope_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: q(3), dq(3)
        call point_values(self%osc, self%seg, self%p, x, q, dq)
        y = dq(self%which)
    end function slope_eval

end module seispulse_sdof_closed
