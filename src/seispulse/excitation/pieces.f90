!> Monotone pieces of a ground acceleration: a generator that cuts the time axis, one
!> interval [ta, tb] at a time, where a_g of a pulse of seispulse_pulses or of a sampled
!> record is continuous and monotone, with the values a_g(ta+) and a_g(tb-) at its ends.
!>
!> Why pieces: on a piece a_g takes its extremes at the ends, so a_g - level has at most
!> one root there, and a sign check at the ends proves whether there is one. Every root
!> an event-driven integrator looks for in a_g (the onset of sliding, the uplift of a
!> rocking block, the split where u'' = a_g - s ay changes sign) is then bracketed
!> by proof, and Brent's method (seispulse_roots) finds the only one. seispulse_sliding_sim
!> and seispulse_rocking_sim both run over these pieces; each loads a piece into its own
!> ground object, so this module knows nothing of sliding or rocking.
!>
!> The pieces (breaks in t) of a pulse: exponential 0, t_d/2, t_d (3t_d/2, 2t_d);
!> half-sine 0, T/2, T; n cosine cycles 0, T/2, T, ..., n T (every extremum); n sine cycles
!> 0, T/4, 3T/4, 5T/4, ..., (n - 1/4) T, n T (every extremum and the end); rectangular 0, T;
!> triangular 0, rT, T. The spike (beta = +inf) has none: it exceeds any threshold at
!> one instant only, with no area. Ricker: from t = 0, breaks at the extrema
!> x = pi f_p (t - t0) = -sqrt(1.5), 0, +sqrt(1.5), the last piece cut at x = 10
!> (|a| < 1e-40 a_p; a_g = 0 after the cut). Mavroeidis & Papageorgiou: the extrema of
!> a_g are not closed form: the window is cut into pieces of 1/(64 f_p), each split at
!> the sign changes of the closed-form jerk (see `mp_next_break`). A record, accel(i)
!> at t = (i - 1) dt and linear in between: each step is a piece.
!> Where a_g jumps (the box at t_d and 2 t_d, the rectangle at T, the cosine cycles at n T,
!> the triangle with r = 1 at T) the values at the ends are the limits from inside the
!> piece. The generator stores nothing that grows with the run.
module seispulse_pieces
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_special, only: pi
    use seispulse_pulses, only: pulse_t, pulse_at, pulse_breaks, exp_consts_t, exp_consts, &
                                PULSE_EXPONENTIAL, PULSE_HALF_SINE, PULSE_SINE_CYCLE, &
                                PULSE_COSINE_CYCLE, PULSE_RECTANGULAR, PULSE_TRIANGULAR, &
                                PULSE_RICKER, PULSE_MP, ricker_x_cut, mp_jerk_t, mp_jerk_of, &
                                mp_jerk_slope
    implicit none
    private

    public :: piece_t, piece_iter_t, pulse_pieces_check, record_pieces_check, record_step_check
    public :: record_in_si, g_product_max
    public :: pulse_pieces_init, record_pieces_init, next_piece, exceeds, onset_on_piece
    public :: record_step, piece_step

    !> M&P: largest gamma accepted (64 gamma coarse pieces are generated).
    real(dp), parameter :: mp_gamma_max = 1.0e6_dp
    !> Mavroeidis-Papageorgiou pieces per 1/f_p before the jerk-sign split.
    integer, parameter :: mp_per_period = 64
    !> M&P: bisection depth of the jerk-root search below one coarse piece.
    integer, parameter :: mp_max_depth = 48

    integer, parameter :: SRC_PULSE = 1, SRC_RECORD = 2

    !> One piece: a_g is continuous and monotone on [ta, tb].
    type :: piece_t
        real(dp) :: ta = 0.0_dp      !! start
        real(dp) :: tb = 0.0_dp      !! end, > ta
        real(dp) :: aa = 0.0_dp      !! a_g(ta+), the limit from inside where a_g jumps
        real(dp) :: ab = 0.0_dp      !! a_g(tb-), the limit from inside where a_g jumps
        real(dp) :: slope = 0.0_dp   !! record step: a_g = aa + slope (t - ta); pulse: 0
    end type piece_t

    !> Generator of the monotone pieces, one at a time (no storage that grows). Set it
    !> up with `pulse_pieces_init` or `record_pieces_init`, then call `next_piece`.
    type :: piece_iter_t
        private
        integer :: src = SRC_PULSE
        ! pulse (SRC_PULSE)
        type(pulse_t) :: p                  !! the pulse
        type(exp_consts_t) :: cexp          !! its beta constants (exponential kind)
        ! fixed break list (pulses other than M&P)
        integer :: nbreaks = 0
        integer :: next = 1
        real(dp) :: breaks(8) = 0.0_dp
        ! sine and cosine cycles: breaks made on the fly (2n + 2 or 2n + 1 of them)
        integer :: cyc = 0                  !! 0 the list above; 1 sine, 2 cosine cycles
        ! record
        integer :: nsamp = 0
        integer :: step = 0
        real(dp) :: dt = 0.0_dp
        ! Mavroeidis & Papageorgiou
        logical :: mp = .false.
        integer :: ncoarse = 0
        integer :: kc = 1
        real(dp) :: x_lo = 0.0_dp
        real(dp) :: t_lo = 0.0_dp
        real(dp) :: half_gamma = 0.0_dp
        real(dp) :: m1 = 0.0_dp             !! bound on |J'|
        real(dp) :: m2 = 0.0_dp             !! bound on |J''|
        logical :: from_root = .false.      !! x_lo is a root of J found before
        real(dp) :: j_lo = 0.0_dp           !! J(x_lo) when x_lo is not a root
        real(dp) :: a_lo = 0.0_dp           !! a_g(t_lo), carried: a_g is continuous
        type(mp_jerk_t) :: jerk             !! J = mp_jerk of seispulse_pulses
    end type piece_iter_t

contains

    !> Can the (valid) pulse be cut into pieces? The M&P window is cut into 64 gamma
    !> coarse pieces, so gamma is limited to mp_gamma_max.
    subroutine pulse_pieces_check(p, integrator, stat, errmsg)
        type(pulse_t), intent(in) :: p                        !! the pulse, valid
        character(len=*), intent(in) :: integrator            !! its user, named in the message
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (p%kind == PULSE_MP) then
            if (p%gamma > mp_gamma_max) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'gamma = ' &
                               //real_str(p%gamma) &
                               //': the '//integrator//' integrator supports gamma <= 1e6')
            end if
        end if
    end subroutine pulse_pieces_check

    !> Can the samples of a record be cut into pieces? At least one sample, and every
    !> sample finite (a step with a NaN or an infinity is no monotone piece).
    subroutine record_pieces_check(accel, stat, errmsg, name)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration samples
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        character(len=*), intent(in), optional :: name        !! of the record (default accel)
        character(len=:), allocatable :: rname
        integer :: i
        stat = SEISPULSE_SUCCESS
        call record_name(name, rname)
        if (size(accel) < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, rname &
                           //': the record is empty (at least one sample is needed)')
            return
        end if
        do i = 1, size(accel)
            if (.not. ieee_is_finite(accel(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, rname &
                               //'('//int_str(i)//') = '//real_str(accel(i)) &
                               //': every sample must be a finite number')
                return
            end if
        end do
    end subroutine record_pieces_check

    !> A record with its time step and gravity, as every analysis on records takes them:
    !> dt and g finite and > 0, then `record_pieces_check` on the samples.
    subroutine record_step_check(accel, dt, g, stat, errmsg, name)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration samples (g)
        real(dp), intent(in) :: dt                            !! time step (s)
        real(dp), intent(in) :: g                             !! gravity (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        character(len=*), intent(in), optional :: name        !! of the record (default accel)
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(dt)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//real_str(dt) &
                           //': must be a finite number > 0 (s)')
        else if (.not. finite_positive(g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g) &
                           //': must be a finite number > 0 (m/s^2)')
        else
            call record_pieces_check(accel, stat, errmsg, name)
        end if
    end subroutine record_step_check

    !> A record in g taken to m/s^2, accel_si = g * accel, every product finite: a sample
    !> whose product would overflow is an error naming it, found before the product.
    subroutine record_in_si(accel, g, accel_si, stat, errmsg, name)
        real(dp), intent(in) :: accel(:)                      !! samples (g), finite
        real(dp), intent(in) :: g                             !! gravity (m/s^2), finite, > 0
        real(dp), allocatable, intent(out) :: accel_si(:)     !! g * accel (m/s^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        character(len=*), intent(in), optional :: name        !! of the record (default accel)
        character(len=:), allocatable :: rname
        real(dp) :: a_max
        integer :: i
        stat = SEISPULSE_SUCCESS
        a_max = g_product_max(g)
        do i = 1, size(accel)
            if (abs(accel(i)) > a_max) then
                call record_name(name, rname)
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, rname &
                               //'('//int_str(i)//') = '//real_str(accel(i)) &
                               //': g * '//rname//' overflows (g = ' &
                               //real_str(g)//' m/s^2)')
                return
            end if
        end do
        allocate(accel_si(size(accel)))
        accel_si(:) = g * accel
    end subroutine record_in_si

    !> Largest |x| whose product g x is sure to be finite (g > 0): huge for g <= 1, else
    !> huge/g less a margin of 4 ulps for the rounding of the quotient and of the product.
    elemental function g_product_max(g) result(x_max)
        real(dp), intent(in) :: g  !! the factor, > 0
        real(dp) :: x_max
        x_max = huge(g)
        if (g > 1.0_dp) x_max = (huge(g) / g) * (1.0_dp - 4.0_dp * epsilon(g))
    end function g_product_max

    !> The pieces of a (valid) pulse: its break list, or the M&P generator state.
    subroutine pulse_pieces_init(it, p)
        type(piece_iter_t), intent(out) :: it  !! the generator, at its first piece
        type(pulse_t), intent(in) :: p         !! the pulse, valid (pulse_validate)
        real(dp) :: td, xs(4), tx, gam, v, d
        integer :: n, k
        it%src = SRC_PULSE
        it%p = p
        if (p%kind == PULSE_EXPONENTIAL) it%cexp = exp_consts(p%beta)   ! once per run
        it%next = 1
        td = p%duration
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            if (p%beta > huge(p%beta)) then
                ! spike: a_g > 0 at one instant only, no area: no piece
                it%nbreaks = 0
            else
                call pulse_breaks(p, it%breaks(1:5), it%nbreaks)
            end if
        case (PULSE_HALF_SINE)
            it%nbreaks = 3
            it%breaks(1:3) = [0.0_dp, 0.5_dp * td, td]
        case (PULSE_COSINE_CYCLE)
            ! k T/2, k = 0 .. 2n (cycle_break)
            it%cyc = 2
            it%nbreaks = 2 * nint(p%cycles) + 1
        case (PULSE_SINE_CYCLE)
            ! 0, (2k - 3) T/4 for k = 2 .. 2n + 1, n T (cycle_break)
            it%cyc = 1
            it%nbreaks = 2 * nint(p%cycles) + 2
        case (PULSE_RICKER)
            ! extrema of (1 - 2x^2) e^(-x^2) at x = 0, +-sqrt(3/2); cut at x = 10
            xs = [-sqrt(1.5_dp), 0.0_dp, sqrt(1.5_dp), ricker_x_cut]
            n = 1
            it%breaks(1) = 0.0_dp
            do k = 1, 4
                tx = p%t0 + xs(k) / (pi * p%freq)
                if (tx > it%breaks(n)) then
                    n = n + 1
                    it%breaks(n) = tx
                end if
            end do
            it%nbreaks = n
        case (PULSE_MP)
            gam = p%gamma
            it%mp = .true.
            it%nbreaks = 0
            it%half_gamma = 0.5_dp * gam
            it%ncoarse = max(1, ceiling(real(mp_per_period, dp) * gam - 1.0e-9_dp))
            it%kc = 1
            it%x_lo = -it%half_gamma
            it%t_lo = p%t0 + it%x_lo / p%freq
            it%from_root = .false.
            call pulse_at(p, it%t_lo, it%a_lo, v, d)
            it%jerk = mp_jerk_of(p)
            ! J = -sum w_j k_j^2 cos(k_j x + nu): |J'| <= sum w_j k_j^3, |J''| <= sum w_j k_j^4
            associate (k => it%jerk%k)
                it%m1 = 0.5_dp * (k(1)**3 + 0.5_dp * (k(2)**3 + k(3)**3))
                it%m2 = 0.5_dp * (k(1)**4 + 0.5_dp * (k(2)**4 + k(3)**4))
            end associate
            it%j_lo = it%jerk%eval(it%x_lo)
        case default
            ! rectangular 0, T; triangular 0, rT, T
            call pulse_breaks(p, it%breaks(1:5), it%nbreaks)
        end select
    end subroutine pulse_pieces_init

    !> The pieces of a record of nsamp samples at interval dt: one piece a step.
    subroutine record_pieces_init(it, nsamp, dt)
        type(piece_iter_t), intent(out) :: it  !! the generator, at its first piece
        integer, intent(in) :: nsamp           !! number of samples (accel(1:nsamp))
        real(dp), intent(in) :: dt             !! sampling interval, > 0
        it%src = SRC_RECORD
        it%nsamp = nsamp
        it%dt = dt
        it%step = 0
    end subroutine record_pieces_init

    !> The name of a record in messages: `name`, or accel. A subroutine, not a function
    !> with a deferred-length result: gfortran keeps such a length in a static variable
    !> of the caller, shared by threads.
    pure subroutine record_name(name, text)
        character(len=*), intent(in), optional :: name
        character(len=:), allocatable, intent(out) :: text
        if (present(name)) then
            text = name
        else
            text = 'accel'
        end if
    end subroutine record_name

    !> Sample step i of a record (from t = (i - 1) dt to i dt, 1 <= i < size(accel)): the
    !> line through accel(i) and accel(i + 1), of slope (accel(i + 1) - accel(i))/dt. The
    !> one form of a record step, for the record of the iterator and for any companion
    !> record sampled with it (a vertical component, a second horizontal one).
    pure function record_step(accel, i, dt) result(piece)
        real(dp), intent(in) :: accel(:)   !! the samples
        integer, intent(in) :: i           !! the step
        real(dp), intent(in) :: dt         !! sampling interval (s)
        type(piece_t) :: piece
        piece = piece_t(real(i - 1, dp) * dt, real(i, dp) * dt, accel(i), accel(i + 1), &
                        (accel(i + 1) - accel(i)) / dt)
    end function record_step

    !> The sample step of the last record piece `next_piece` returned (0 before the first).
    pure function piece_step(it) result(i)
        type(piece_iter_t), intent(in) :: it  !! a record's generator
        integer :: i
        i = it%step
    end function piece_step

    !> Next piece [ta, tb] of positive length, a_g(ta+) = aa and a_g(tb-) = ab; found is
    !> false when there is none left. On a record step a_g is the line through (ta, aa)
    !> of slope (ab - aa)/dt (computed with dt, not tb - ta); a pulse piece has slope 0
    !> (a_g there comes from the closed form). The piece comes back as one derived type,
    !> not as five scalars: gfortran (12, -O2) then stores ta, tb and aa, ab in pairs, as
    !> the callers load them; a pair loaded from two scalar stores misses store-to-load
    !> forwarding, which made a long record 1.6 times slower in seispulse_sliding_sim.
    subroutine next_piece(it, accel, caller, piece, found, stat, errmsg)
        type(piece_iter_t), intent(inout) :: it  !! the generator
        real(dp), intent(in) :: accel(:)         !! the record's samples (any size for a pulse)
        character(len=*), intent(in) :: caller   !! the calling module, first word of messages
        type(piece_t), intent(out) :: piece      !! the piece (zeros when none is found)
        logical, intent(out) :: found            !! a piece was returned
        integer, intent(out) :: stat             !! SEISPULSE_SUCCESS or SEISPULSE_INTERNAL
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: v, d, xe, xb, ta, tb, aa, ab
        integer :: i
        stat = SEISPULSE_SUCCESS
        found = .false.
        if (it%src == SRC_RECORD) then
            if (it%step >= it%nsamp - 1) return
            it%step = it%step + 1
            i = it%step
            piece = record_step(accel, i, it%dt)
            found = .true.
        else if (it%mp) then
            do while (it%kc <= it%ncoarse)
                if (it%kc == it%ncoarse) then
                    xe = it%half_gamma
                else
                    xe = -it%half_gamma + real(it%kc, dp) / real(mp_per_period, dp)
                end if
                call mp_next_break(it, xe, caller, xb, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                if (xb >= xe) then
                    xb = xe
                    it%kc = it%kc + 1
                    it%from_root = .false.
                else
                    it%from_root = .true.
                end if
                it%x_lo = xb
                ta = it%t_lo
                tb = it%p%t0 + xb / it%p%freq
                if (tb > ta) then
                    it%t_lo = tb
                    aa = it%a_lo
                    call pulse_at(it%p, tb, ab, v, d, it%cexp)
                    it%a_lo = ab
                    piece = piece_t(ta, tb, aa, ab, 0.0_dp)
                    found = .true.
                    return
                end if
            end do
        else
            do while (it%next < it%nbreaks)
                if (it%cyc == 0) then
                    ta = it%breaks(it%next)
                    tb = it%breaks(it%next + 1)
                else
                    ta = cycle_break(it, it%next)
                    tb = cycle_break(it, it%next + 1)
                end if
                it%next = it%next + 1
                if (tb > ta) then
                    call pulse_at(it%p, ta, aa, v, d, it%cexp)
                    ab = accel_before(it%p, tb)
                    piece = piece_t(ta, tb, aa, ab, 0.0_dp)
                    found = .true.
                    return
                end if
            end do
        end if
    end subroutine next_piece

    !> Break k (s) of n sine (it%cyc = 1) or cosine (2) cycles of period T: the extrema of
    !> a_g and the ends. Sine: 0, then (2k - 3) T/4 for k = 2 .. 2n + 1, then n T; cosine:
    !> (k - 1) T/2 for k = 1 .. 2n + 1. The factors are exact (multiples of 1/4 below 2^50),
    !> so n = 1 gives 0, T/4, 3T/4, T and 0, T/2, T, and the last break is n T, the end
    !> time of seispulse_pulses.
    pure function cycle_break(it, k) result(t)
        type(piece_iter_t), intent(in) :: it
        integer, intent(in) :: k
        real(dp) :: t
        if (it%cyc == 1) then
            if (k <= 1) then
                t = 0.0_dp
            else if (k >= it%nbreaks) then
                t = it%p%duration * it%p%cycles
            else
                t = (0.25_dp * real(2 * k - 3, dp)) * it%p%duration
            end if
        else
            t = (0.5_dp * real(k - 1, dp)) * it%p%duration
        end if
    end function cycle_break

    !> a_g just before the break t (left limit): pulse_at is right-continuous, so it
    !> differs only where the pulse jumps: the box (beta = -inf) at t_d and 2 t_d,
    !> the rectangle at T, the cosine cycles at n T, the triangle with r = 1 at T.
    pure function accel_before(p, t) result(a)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: t
        real(dp) :: a
        real(dp) :: v, d
        call pulse_at(p, t, a, v, d)
        select case (p%kind)
        case (PULSE_EXPONENTIAL)
            if (p%beta < -huge(p%beta)) then
                if (t > p%duration) then
                    a = -p%amp
                else
                    a = p%amp
                end if
            end if
        case (PULSE_RECTANGULAR)
            if (t >= p%duration) a = p%amp
        case (PULSE_COSINE_CYCLE)
            if (t >= p%duration * p%cycles) a = p%amp
        case (PULSE_TRIANGULAR)
            if (t >= p%duration .and. p%peak_frac >= 1.0_dp) a = p%amp
        end select
    end function accel_before

    !> M&P: the first sign change of the jerk J in (x_lo, xe), or xe if none.
    !>
    !> v = (A/2)[cos(k0 x + nu) + (cos(kp x + nu) + cos(km x + nu))/2] with x = f_p (t - t0),
    !> k0 = 2 pi, kp, km = 2 pi (1 +- 1/gamma) (product-to-sum form of Eq. 1 of M&P 2003),
    !> so J = (d^2 v/dx^2)/A (mp_jerk of seispulse_pulses) is a sum of three cosines with
    !> |J'| <= m1, |J''| <= m2.
    !> An interval [lo, hi] of midpoint m and width h has no root when |J(m)| > m1 h/2,
    !> and J is monotone on it (one root at most, found by Brent if J changes sign)
    !> when |J'(m)| > m2 h/2; otherwise it is halved. Only a tangency of J (a double
    !> root: a_g has an inflection with zero slope there) can reach the depth limit,
    !> where the plain sign test is used; a_g is then monotone up to a variation of
    !> order m1 h^3 with h = 2^-48/64, far below the rounding of a_g.
    subroutine mp_next_break(it, xe, caller, xb, stat, errmsg)
        type(piece_iter_t), intent(inout) :: it
        real(dp), intent(in) :: xe
        character(len=*), intent(in) :: caller
        real(dp), intent(out) :: xb
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: stack(mp_max_depth + 1), jstack(mp_max_depth + 1), lo, hi, h, xm, jlo, jhi, jm
        integer :: n, iter
        logical :: done
        character(len=120) :: rmsg
        stat = SEISPULSE_SUCCESS
        xb = xe
        lo = it%x_lo
        ! a root found before: J is monotone just after it, so no new root there
        if (it%from_root) then
            jlo = 0.0_dp
        else
            jlo = it%j_lo
        end if
        ! J at the right ends of the pending intervals, each evaluated once
        n = 1
        stack(1) = xe
        jstack(1) = it%jerk%eval(xe)
        ! each pass either halves an interval (depth <= mp_max_depth) or retires one
        do iter = 1, 100000
            hi = stack(n)
            h = hi - lo
            xm = lo + 0.5_dp * h
            jhi = jstack(n)
            jm = it%jerk%eval(xm)
            done = .false.
            if (abs(jm) > 0.5_dp * it%m1 * h) then
                done = .true.
            else if (abs(mp_jerk_slope(it%jerk, xm)) > 0.5_dp * it%m2 * h &
                     .or. n > mp_max_depth) then
                if ((jlo < 0.0_dp .and. jhi > 0.0_dp) .or. (jlo > 0.0_dp .and. jhi < 0.0_dp)) then
                    call find_root(it%jerk, lo, hi, xb, stat, rmsg, fa_known=jlo, fb_known=jhi)
                    if (stat /= SEISPULSE_SUCCESS) then
                        call set_error(stat, errmsg, SEISPULSE_INTERNAL, &
                                       caller//': M&P jerk root: '//trim(rmsg)//' (a bug)')
                        return
                    end if
                    xb = min(max(xb, lo), hi)
                    return
                end if
                done = .true.
            else
                n = n + 1
                stack(n) = xm
                jstack(n) = jm
            end if
            if (done) then
                lo = hi
                jlo = jhi
                n = n - 1
                if (n == 0) then
                    xb = xe
                    it%j_lo = jhi
                    return
                end if
            end if
        end do
        call set_error(stat, errmsg, SEISPULSE_INTERNAL, &
                       caller//': M&P jerk roots: search did not end (a bug)')
    end subroutine mp_next_break

    ! ------------------------------------------------------------------------------
    ! Onset from rest on a piece (sliding and rocking blocks alike)
    ! ------------------------------------------------------------------------------

    !> a exceeds thr by more than rounding (two ulps of the larger): a threshold that
    !> is only touched starts no motion. Safe for thr = +inf (no inf - inf).
    elemental logical function exceeds(a, thr)
        real(dp), intent(in) :: a    !! the value (any unit)
        real(dp), intent(in) :: thr  !! the threshold (unit of a; +inf allowed)
        exceeds = a - thr > 2.0_dp * epsilon(a) * max(abs(a), abs(thr))
    end function exceeds

    !> Does a block at rest start moving on a piece where a_g is monotone, from a_start
    !> at its start to a_end at its end (m/s^2)? Motion in +x starts when a_g exceeds
    !> thr_pos, in -x when -a_g exceeds thr_neg; `blocked` (+1 or -1, 0: none) excludes
    !> one direction. dir = +1, -1 or 0 (none on this piece); now: at the start of the
    !> piece, else where a_g crosses lev (the root the caller locates).
    pure subroutine onset_on_piece(a_start, a_end, thr_pos, thr_neg, blocked, dir, lev, now)
        real(dp), intent(in) :: a_start  !! a_g at the start of the piece (m/s^2)
        real(dp), intent(in) :: a_end    !! a_g at its end (m/s^2)
        real(dp), intent(in) :: thr_pos  !! threshold of motion in +x (m/s^2), >= 0 or +inf
        real(dp), intent(in) :: thr_neg  !! threshold of motion in -x (m/s^2), >= 0 or +inf
        integer, intent(in) :: blocked   !! +1 or -1: that direction excluded; 0: none
        integer, intent(out) :: dir      !! +1, -1, or 0 (no onset on this piece)
        real(dp), intent(out) :: lev     !! the a_g level (m/s^2) whose crossing starts motion
        logical, intent(out) :: now      !! motion starts at the start of the piece
        dir = 0
        lev = 0.0_dp
        now = .false.
        if (blocked /= 1 .and. exceeds(a_start, thr_pos)) then
            dir = 1
            now = .true.
        else if (blocked /= -1 .and. exceeds(-a_start, thr_neg)) then
            dir = -1
            now = .true.
        else if (blocked /= 1 .and. exceeds(a_end, thr_pos)) then
            dir = 1
            lev = thr_pos
            now = .not. (a_start < thr_pos)
        else if (blocked /= -1 .and. exceeds(-a_end, thr_neg)) then
            dir = -1
            lev = -thr_neg
            now = .not. (a_start > -thr_neg)
        end if
    end subroutine onset_on_piece

end module seispulse_pieces
