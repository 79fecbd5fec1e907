!> Newmark rigid-block sliding on accelerograms: one-way (downslope) sliding as
!> SLAMMER does it, two-way sliding, and asymmetric yields with the along-plane
!> factors of a real incline (doc/sliding.md section 7, Eq. 1.31).
!>
!> The block slides relative to the ground with (doc/sliding.md Eq. 1.3)
!>     u'' = K_dir g (a_g(t) - s ky_dir)        while sliding in direction s = sgn(u'),
!> and sticks while -ky_up <= a_g <= ky. Positive a_g drives positive (downslope)
!> sliding; K_dir = 1 except on an incline (newmark_incline).
!>
!> Two integration rules:
!>  - NEWMARK_EXACT: a_g is linear between samples, so on each step the relative
!>    velocity is a quadratic and the displacement a cubic in time; onsets (a_g
!>    crossing a yield: linear) and stops (the velocity's first root: a stable
!>    quadratic formula) are located inside the step. This is the exact solution
!>    of the piecewise-linear record, the same problem the event-driven integrator
!>    of seispulse_sliding_sim solves (a_g = 0 after the last sample, so a block still
!>    sliding there decelerates to rest), but without root iterations: a few flops
!>    per step.
!>  - NEWMARK_SLAMMER: SLAMMER 1.1's rigorous rigid-block loop (Jibson et al. 2013,
!>    RigidBlock.NewmarkRigorous), step for step: units of cm/s^2 with g = 100 g
!>    (980.665 for standard gravity), the trapezoidal rule on y = a - n ky for the
!>    velocity and on the velocity for the displacement, the block stopped when the
!>    velocity reaches zero (one way) or changes sign (two ways, SLAMMER's dual-slope
!>    test without its g sin(slope) shift). Each sample is one step from the state
!>    after the previous one (the state before the first sample is zero), and the
!>    record ends at the last sample. Not reproduced: SLAMMER skips samples that are
!>    exactly 0 for a positive scale factor only (no effect unless such samples fall
!>    inside a slide; the 18 records of its test set have none).
module seispulse_newmark
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_checks, only: positive
    use seispulse_optval, only: optval
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str, int_str, name_of, name_len, code_of
    use seispulse_sliding_sim, only: slide_t
    use seispulse_pieces, only: record_step_check
    use seispulse_sliding_closed, only: inclined_resistances
    use seispulse_flexible_model, only: ky_table_validate, ky_table_at
    use seispulse_flexible_exact, only: zero_function, first_zero
    use seispulse_roots, only: find_root
    use seispulse_special, only: inv_fact => inv_factorial
    implicit none
    private

    public :: newmark_block_t, newmark_result_t
    public :: newmark_rigid, newmark_incline, newmark_block_validate
    public :: newmark_mode_name, newmark_method_name, newmark_mode_code, newmark_method_code
    public :: NEWMARK_DOWN, NEWMARK_BOTH, NEWMARK_ASYM, NEWMARK_EXACT, NEWMARK_SLAMMER

    integer, parameter :: NEWMARK_DOWN = 1     !! one-way: downslope (positive) sliding only
    integer, parameter :: NEWMARK_BOTH = 2     !! two-way, the same yield both ways
    integer, parameter :: NEWMARK_ASYM = 3     !! two-way, ky down and ky_up up, factors K
    integer, parameter :: NEWMARK_EXACT = 1    !! exact piecewise-linear integration
    integer, parameter :: NEWMARK_SLAMMER = 2  !! SLAMMER 1.1's trapezoidal loop

    character(len=*), parameter :: mode_names(3) = [character(len=4) :: 'down', 'both', 'asym']
    character(len=*), parameter :: method_names(2) = [character(len=7) :: 'exact', 'slammer']

    !> Events allowed in one step; a handful are possible (stop, reversal, stop,
    !> onset), so reaching this is a bug, reported as such.
    integer, parameter :: max_events = 8
    !> Turning points of the speed searched in one piece of a table slide.
    integer, parameter :: max_turns = 1000
    !> Steps of the run-out of a table slide after the record (beyond: closed form on the
    !> last row, or an error).
    integer, parameter :: max_runout = 10000000

    !> SLAMMER's "at rest" test on the velocity (cm/s).
    real(dp), parameter :: slammer_rest = 1.0e-15_dp

    !> The sliding block: yield accelerations (g) and, for an incline, the factors that
    !> turn the slip of the yield problem into the slip along the plane.
    type :: newmark_block_t
        integer :: mode = NEWMARK_DOWN   !! NEWMARK_DOWN, NEWMARK_BOTH or NEWMARK_ASYM
        real(dp) :: ky = 0.1_dp          !! yield acceleration downslope (g), > 0 (+inf: never)
        real(dp) :: ky_up = 0.1_dp       !! yield acceleration upslope (g), > 0 (ASYM only)
        real(dp) :: k_down = 1.0_dp      !! along-plane factor downslope, > 0 (ASYM only)
        real(dp) :: k_up = 1.0_dp        !! along-plane factor upslope, > 0 (ASYM only)
        !> Yield table (DOWN only; then ky is ignored): ky(u) interpolated linearly in the
        !> sliding displacement u, constant beyond the last row (doc/newmark.md section 5).
        real(dp), allocatable :: ky_disp(:)    !! displacements (m): 0 first, increasing
        real(dp), allocatable :: ky_values(:)  !! yields (g) > 0
    end type newmark_block_t

    !> Result of one analysis (SI).
    type :: newmark_result_t
        real(dp) :: max_disp = 0.0_dp    !! largest |u| over time (m)
        real(dp) :: final_disp = 0.0_dp  !! u when the block is finally at rest (m), signed
        real(dp) :: u_max = 0.0_dp       !! largest u (m), >= 0
        real(dp) :: u_min = 0.0_dp       !! smallest u (m), <= 0
        real(dp) :: max_vel = 0.0_dp     !! largest |u'| (m/s)
        real(dp) :: t_end = 0.0_dp       !! end of the last slide (s from the first sample)
        type(slide_t), allocatable :: slides(:)  !! sliding intervals (times s, u m, u' m/s)
    end type newmark_result_t

    !> A slide on one segment of a yield table (rigid_exact_table, (N.8)): Y = U - U0 from
    !> speed w0 with Y'' = -kappa Y + f0 + f1 tau (g units).
    type, extends(zero_function) :: table_slide_t
        real(dp) :: kappa = 0.0_dp  !! d ky/d U (1/s^2)
        real(dp) :: w0 = 0.0_dp     !! speed at the start (g s)
        real(dp) :: f0 = 0.0_dp     !! a - ky at the start (g)
        real(dp) :: f1 = 0.0_dp     !! slope of a (g/s)
        real(dp) :: target = 0.0_dp !! Y at the segment end (mode 1)
        real(dp) :: x0 = 0.0_dp     !! origin of f in mode 2 (s)
        real(dp) :: zsign = 1.0_dp  !! sign of f in mode 2
        integer :: mode = 0         !! 0: f = Y', 1: f = Y - target, 2: f = zsign Y''(x0 + x)
    contains
        procedure :: taylor => table_taylor
        procedure :: disp => table_disp
        procedure :: vel => table_vel
        procedure :: bound => table_bound
    end type table_slide_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Check a block; the message names the offending parameter.
    subroutine newmark_block_validate(blk, stat, errmsg)
        type(newmark_block_t), intent(in) :: blk              !! the block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (allocated(blk%ky_disp) .or. allocated(blk%ky_values)) then
            if (.not. (allocated(blk%ky_disp) .and. allocated(blk%ky_values))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp, ky_values: ' &
                               //'give both or neither')
            else if (blk%mode /= NEWMARK_DOWN) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode: a yield table ' &
                               //'(ky_disp, ky_values) needs mode down (one-way sliding)')
            else
                call ky_table_validate(blk%ky_disp, blk%ky_values, stat, errmsg)
            end if
            return
        end if
        if (blk%mode < NEWMARK_DOWN .or. blk%mode > NEWMARK_ASYM) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode: unknown code (allowed:' &
                           //' 1 down, 2 both, 3 asym)')
        else if (.not. positive(blk%ky)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = '//real_str(blk%ky) &
                           //': must be > 0 (g)')
        else if (blk%mode == NEWMARK_ASYM) then
            if (.not. positive(blk%ky_up)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_up = ' &
                               //real_str(blk%ky_up)//': must be > 0 (g; +inf: no upslope sliding)')
            else if (.not. factor_ok(blk%k_down, blk%ky)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'k_down = ' &
                               //real_str(blk%k_down)//': must be a finite number > 0')
            else if (.not. factor_ok(blk%k_up, blk%ky_up)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'k_up = ' &
                               //real_str(blk%k_up)//': must be a finite number > 0')
            end if
        end if
    end subroutine newmark_block_validate

    !> The block on an incline of slope lambda with friction mu, shaken at angle xi to
    !> the horizontal (the record is that component, positive downhill): yields and
    !> along-plane factors of doc/sliding.md Eq. 1.31 and section 7 (an asymmetric block).
    !> Without along_plane the factors are 1 (the slip of the yield problem, as SLAMMER).
    !> xi_deg and along_plane are optional (defaults as Python's `newmark.incline`);
    !> when one is omitted, pass blk and stat by keyword.
    subroutine newmark_incline(mu, slope_deg, xi_deg, along_plane, blk, stat, errmsg)
        real(dp), intent(in) :: mu                            !! friction coefficient > 0
        real(dp), intent(in) :: slope_deg                     !! lambda in [0, 90) deg, < atan mu
        !> xi in [-90, 90] deg; default 0 (horizontal excitation)
        real(dp), intent(in), optional :: xi_deg
        !> apply K1, K2; default .true.
        logical, intent(in), optional :: along_plane
        type(newmark_block_t), intent(out) :: blk             !! mode NEWMARK_ASYM
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: eta1, eta2, k1, k2
        ! with A_g = 1 g the resistances over A_g are the yields in g
        real(dp) :: xi_in
        logical :: along_in
        xi_in = optval(xi_deg, 0.0_dp)
        along_in = optval(along_plane, .true.)
        call inclined_resistances(mu, 1.0_dp, slope_deg, xi_in, eta1, eta2, k1, k2, &
                                  stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        blk%mode = NEWMARK_ASYM
        blk%ky = eta1
        blk%ky_up = eta2
        blk%k_down = 1.0_dp
        blk%k_up = 1.0_dp
        if (along_in) then
            ! a direction that cannot slide (eta = +inf) has K = 0: keep 1, it is unused
            if (k1 > 0.0_dp) blk%k_down = k1
            if (k2 > 0.0_dp) blk%k_up = k2
        end if
    end subroutine newmark_incline

    !> Rigid-block sliding on a record: accel(i) (g) at t = (i - 1) dt.
    !>
    !> Histories (optional, each of size(accel)): relative displacement u (m) and
    !> velocity u' (m/s) at the sample times; for NEWMARK_SLAMMER the values after
    !> SLAMMER's step of each sample.
    subroutine newmark_rigid(accel, dt, blk, method, g, res, stat, errmsg, u_hist, w_hist)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g), finite
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        type(newmark_block_t), intent(in) :: blk              !! yields and mode
        integer, intent(in) :: method                         !! NEWMARK_EXACT or NEWMARK_SLAMMER
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        type(newmark_result_t), intent(out) :: res            !! the result
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(out), optional :: u_hist(:)          !! u at the samples (m)
        real(dp), intent(out), optional :: w_hist(:)          !! u' at the samples (m/s)
        real(dp) :: ay_up, k_down, k_up

        allocate(res%slides(0))
        call newmark_block_validate(blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (method /= NEWMARK_EXACT .and. method /= NEWMARK_SLAMMER) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'method: unknown code ' &
                           //'(allowed: 1 exact, 2 slammer)')
            return
        end if
        call record_step_check(accel, dt, g, stat, errmsg)   ! dt, g; not empty, finite
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. same_size(u_hist, 'u_hist')) return
        if (.not. same_size(w_hist, 'w_hist')) return

        k_down = 1.0_dp
        k_up = 1.0_dp
        select case (blk%mode)
        case (NEWMARK_DOWN)
            ay_up = ieee_value(ay_up, ieee_positive_inf)
        case (NEWMARK_BOTH)
            ay_up = blk%ky
        case default
            ay_up = blk%ky_up
            k_down = blk%k_down
            k_up = blk%k_up
        end select

        if (allocated(blk%ky_disp)) then
            if (size(blk%ky_disp) == 1) then
                ! one row: the constant yield (the same arithmetic, bit for bit)
                if (method == NEWMARK_EXACT) then
                    call rigid_exact(accel, dt, blk%ky_values(1), ay_up, k_down, k_up, g, res, &
                                     stat, errmsg, u_hist, w_hist)
                else
                    call rigid_slammer(accel, dt, blk%ky_values(1), ay_up, k_down, k_up, .true., &
                                       g, res, u_hist, w_hist)
                end if
            else if (method == NEWMARK_EXACT) then
                call rigid_exact_table(accel, dt, blk%ky_disp, blk%ky_values, g, res, stat, &
                                       errmsg, u_hist, w_hist)
            else
                call rigid_slammer(accel, dt, blk%ky_values(1), ay_up, k_down, k_up, .true., &
                                   g, res, u_hist, w_hist, blk%ky_disp, blk%ky_values)
            end if
        else if (method == NEWMARK_EXACT) then
            call rigid_exact(accel, dt, blk%ky, ay_up, k_down, k_up, g, res, stat, errmsg, &
                             u_hist, w_hist)
        else
            call rigid_slammer(accel, dt, blk%ky, ay_up, k_down, k_up, blk%mode == NEWMARK_DOWN, &
                               g, res, u_hist, w_hist)
        end if
    contains

        !> An optional history has the size of accel (else an error naming it).
        logical function same_size(hist, name)
            real(dp), intent(in), optional :: hist(:)
            character(len=*), intent(in) :: name
            same_size = .true.
            if (.not. present(hist)) return
            same_size = size(hist) == size(accel)
            if (.not. same_size) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name &
                                                //': must have the size of accel')
        end function same_size

    end subroutine newmark_rigid

    !> Name of a mode code ('down', 'both', 'asym'; '?' if unknown).
    pure function newmark_mode_name(code) result(name)
        integer, intent(in) :: code  !! NEWMARK_DOWN, NEWMARK_BOTH or NEWMARK_ASYM
        character(len=name_len(code, mode_names)) :: name
        name = name_of(code, mode_names)
    end function newmark_mode_name

    !> Name of a method code ('exact', 'slammer'; '?' if unknown).
    pure function newmark_method_name(code) result(name)
        integer, intent(in) :: code  !! NEWMARK_EXACT or NEWMARK_SLAMMER
        character(len=name_len(code, method_names)) :: name
        name = name_of(code, method_names)
    end function newmark_method_name

    !> Code of a mode name (0 if unknown).
    pure integer function newmark_mode_code(name)
        character(len=*), intent(in) :: name  !! 'down', 'both' or 'asym'
        newmark_mode_code = code_of(name, mode_names)
    end function newmark_mode_code

    !> Code of a method name (0 if unknown).
    pure integer function newmark_method_code(name)
        character(len=*), intent(in) :: name  !! 'exact' or 'slammer'
        newmark_method_code = code_of(name, method_names)
    end function newmark_method_code

    ! ------------------------------------------------------------------------------
    ! Exact piecewise-linear integration
    ! ------------------------------------------------------------------------------

    !> The exact solution. Internally accelerations are in g, velocities in g s and
    !> displacements in g s^2 (one multiplication by g at the end). While sliding in
    !> direction s the speed z = s u'/K obeys z' = s a_g - ky_s; on a step where a_g
    !> runs linearly from a_s to a_e over h, z(x) = z0 + b x + c x^2 with b = s a_s - ky_s,
    !> c = s (a_e - a_s)/(2 h), and the slip is K (z0 x + b x^2/2 + c x^3/3).
    subroutine rigid_exact(accel, dt, ay_dn, ay_up, k_dn, k_up, g, res, stat, errmsg, &
                           u_hist, w_hist)
        real(dp), intent(in) :: accel(:), dt, ay_dn, ay_up, k_dn, k_up, g
        type(newmark_result_t), intent(inout) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(out), optional :: u_hist(:), w_hist(:)

        type(slide_t), allocatable :: buf(:)
        integer :: n, i, dir, nsl, nev, dnew, stopped_dir
        real(dp) :: u, z, ay, kf, a0, a1, x, as, h, b, c, z1, xs, xv, xo, ao, sgn
        real(dp) :: zpk, tpk, t0
        logical :: stopped, want_u, want_w

        stat = SEISPULSE_SUCCESS
        n = size(accel)
        want_u = present(u_hist)
        want_w = present(w_hist)
        allocate(buf(8))
        nsl = 0
        u = 0.0_dp
        z = 0.0_dp
        dir = 0
        ay = 0.0_dp
        kf = 0.0_dp
        sgn = 0.0_dp
        zpk = 0.0_dp
        tpk = 0.0_dp
        if (want_u) u_hist(1) = 0.0_dp
        if (want_w) w_hist(1) = 0.0_dp

        ! a slide may start at the first sample itself
        if (exceeds(accel(1), ay_dn)) then
            call start_slide(1, 0.0_dp, .false.)
        else if (exceeds(-accel(1), ay_up)) then
            call start_slide(-1, 0.0_dp, .false.)
        end if

        do i = 1, n - 1
            a0 = accel(i)
            a1 = accel(i + 1)
            t0 = real(i - 1, dp) * dt
            if (dir == 0) then
                ! at rest with a_g inside the yields at both ends: nothing happens
                if (a1 <= ay_dn .and. -a1 <= ay_up .and. a0 <= ay_dn .and. -a0 <= ay_up) then
                    if (want_u) u_hist(i + 1) = u
                    if (want_w) w_hist(i + 1) = 0.0_dp
                    cycle
                end if
            end if
            ! events inside the step: x is the time from the step start, as = a_g(x);
            ! stopped_dir: direction of a slide that stopped at x (0: none)
            x = 0.0_dp
            as = a0
            stopped_dir = 0
            events: do nev = 1, max_events + 1
                if (nev > max_events) then
                    call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'newmark: too many ' &
                                   //'events in one step near t = '//real_str(t0)//' (a bug)')
                    return
                end if
                h = dt - x
                if (dir /= 0) then
                    ! ---- sliding from x to dt, or to the stop
                    if (.not. (h > 0.0_dp)) exit events   ! started at the step's end
                    b = sgn * as - ay
                    c = sgn * (a1 - as) / (2.0_dp * h)
                    z1 = z + h * (sgn * 0.5_dp * (as + a1) - ay)
                    stopped = .not. (z1 > 0.0_dp)
                    if (.not. stopped .and. c > 0.0_dp .and. b < 0.0_dp) then
                        ! convex: the minimum z - b^2/(4c) may reach zero inside the step
                        xv = -b / (2.0_dp * c)
                        if (xv < h) stopped = .not. (z + 0.5_dp * b * xv > 0.0_dp)
                    end if
                    if (c < 0.0_dp .and. b > 0.0_dp) then
                        ! concave: the peak speed may be inside the step (before any stop)
                        xv = -b / (2.0_dp * c)
                        if (xv < h) call peak(z + 0.5_dp * b * xv, t0 + x + xv)
                    end if
                    if (.not. stopped) then
                        u = u + sgn * kf * h * (z + h * (0.5_dp * b + h * c / 3.0_dp))
                        z = z1
                        call peak(z, t0 + dt)
                        exit events
                    end if
                    xs = first_root(z, b, c, h)
                    u = u + sgn * kf * xs * (z + xs * (0.5_dp * b + xs * c / 3.0_dp))
                    x = x + xs
                    as = as + (a1 - as) * (xs / h)
                    stopped_dir = dir
                    call stop_slide(t0 + x)
                end if
                ! ---- at rest from x: an onset now (the reverse at once after a stop is
                ! the "slip" of doc/sliding.md section 5), or where a_g crosses a yield (a_g is
                ! linear: one crossing). The direction that just stopped had
                ! s a_g <= ky there: it may start again only by a crossing.
                if (stopped_dir /= 1 .and. exceeds(as, ay_dn)) then
                    call start_slide(1, t0 + x, stopped_dir /= 0)
                    cycle events
                else if (stopped_dir /= -1 .and. exceeds(-as, ay_up)) then
                    call start_slide(-1, t0 + x, stopped_dir /= 0)
                    cycle events
                end if
                if (.not. (x < dt)) exit events
                if (exceeds(a1, ay_dn)) then
                    xo = x
                    if (a1 > as) xo = x + (dt - x) * (max(ay_dn - as, 0.0_dp) / (a1 - as))
                    ao = ay_dn
                    dnew = 1
                else if (exceeds(-a1, ay_up)) then
                    xo = x
                    if (as > a1) xo = x + (dt - x) * (max(as + ay_up, 0.0_dp) / (as - a1))
                    ao = -ay_up
                    dnew = -1
                else
                    exit events
                end if
                if (.not. (xo < dt)) exit events   ! at the step's end: the next step starts it
                x = max(xo, x)
                as = ao
                stopped_dir = 0
                call start_slide(dnew, t0 + x, .false.)
            end do events
            if (want_u) u_hist(i + 1) = u
            if (want_w) w_hist(i + 1) = sgn * kf * z * g
        end do

        ! after the record a_g = 0: a sliding block decelerates to rest in z/ky
        t0 = real(n - 1, dp) * dt
        if (dir /= 0) then
            if (ay < z / huge(z)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky: too small for ' &
                               //'the final sliding velocity (the stop time overflows)')
                return
            end if
            xs = z / ay
            u = u + sgn * kf * 0.5_dp * z * xs
            call stop_slide(t0 + xs)
        end if

        ! to SI
        res%final_disp = g * u
        if (want_u) u_hist = g * u_hist
        res%u_max = g * res%u_max
        res%u_min = g * res%u_min
        res%max_disp = max(res%u_max, -res%u_min)
        call slides_to_si(buf, nsl, g, res)

    contains

        subroutine start_slide(d, t, from_slip)
            integer, intent(in) :: d
            real(dp), intent(in) :: t
            logical, intent(in) :: from_slip
            dir = d
            sgn = real(d, dp)
            if (d > 0) then
                ay = ay_dn
                kf = k_dn
            else
                ay = ay_up
                kf = k_up
            end if
            z = 0.0_dp
            zpk = 0.0_dp
            tpk = t
            call append_slide(buf, nsl, slide_t(direction=d, t_start=t, u_start=u, &
                                                 t_peak=t, from_slip=from_slip))
        end subroutine start_slide

        subroutine stop_slide(t)
            real(dp), intent(in) :: t
            buf(nsl)%t_stop = t
            buf(nsl)%u_stop = u
            buf(nsl)%w_peak = kf * zpk
            buf(nsl)%t_peak = tpk
            res%u_max = max(res%u_max, u)
            res%u_min = min(res%u_min, u)
            res%t_end = t
            dir = 0
            z = 0.0_dp
        end subroutine stop_slide

        subroutine peak(zz, t)
            real(dp), intent(in) :: zz, t
            if (zz > zpk) then
                zpk = zz
                tpk = t
            end if
        end subroutine peak

    end subroutine rigid_exact

    ! ------------------------------------------------------------------------------
    ! Exact integration with a yield table
    ! ------------------------------------------------------------------------------

    !> The exact solution with ky(u) from a table (doc/newmark.md (N.7)-(N.9)), in the units
    !> of rigid_exact (g, g s, g s^2). On a table segment ky = k_i + kappa (U - D_i), so a slide
    !> obeys Y'' = -kappa Y + f0 + f1 tau (Y = U - U0) with the closed form
    !>     Y = W0 tau c1 + f0 tau^2 c2 + f1 tau^3 c3,  Y' = W0 c0 + f0 tau c1 + f1 tau^2 c2 (N.8)
    !> (c_k the Stumpff functions of kappa tau^2, any sign of kappa). The stop (first zero of
    !> Y') comes from first_zero with the bound (N.9) on |Y''''| = |kappa Y''|; a segment end
    !> (U increasing up to the stop: one crossing) by Brent's method. Peak speeds are taken
    !> at the samples and events.
    subroutine rigid_exact_table(accel, dt, kd, kv, g, res, stat, errmsg, u_hist, w_hist)
        real(dp), intent(in) :: accel(:), dt, kd(:), kv(:), g
        type(newmark_result_t), intent(inout) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(out), optional :: u_hist(:), w_hist(:)

        type(slide_t), allocatable :: buf(:)
        type(table_slide_t) :: ph
        real(dp) :: dd(size(kd))
        real(dp) :: u, w, x, h, as, a0, a1, t0, fa(0:2), fb(0:2), m3, xs, xb, ky_now, xo, wpk
        real(dp) :: tpk, kmin, rl
        integer :: n, i, k, nev, nt, seg, lim
        logical :: sliding, found, want_u, want_w, closed

        stat = SEISPULSE_SUCCESS
        n = size(accel)
        nt = size(kd)
        dd = kd / g
        kmin = minval(kv)
        want_u = present(u_hist)
        want_w = present(w_hist)
        allocate(buf(8))
        k = 0
        u = 0.0_dp
        w = 0.0_dp
        seg = 1
        sliding = .false.
        wpk = 0.0_dp
        tpk = 0.0_dp
        if (want_u) u_hist(1) = 0.0_dp
        if (want_w) w_hist(1) = 0.0_dp
        ky_now = table_ky(u)
        if (exceeds(accel(1), ky_now)) call start(0.0_dp)

        lim = n - 1
        closed = .false.
        i = 0
        steps: do while (i < lim)
            i = i + 1
            t0 = real(i - 1, dp) * dt
            if (i <= n - 1) then
                a0 = accel(i)
                a1 = accel(i + 1)
            else
                if (.not. sliding) exit steps
                if (closed .and. seg == nt) then
                    ! a long run-out on the last row (ky constant, a = 0): it stops after
                    ! w/ky (as in rigid_exact)
                    if (kv(nt) < w / huge(w)) then
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_values: ' &
                                       //'too small for the final sliding velocity (the ' &
                                       //'stop time overflows)')
                        return
                    end if
                    xs = w / kv(nt)
                    u = u + 0.5_dp * w * xs
                    w = 0.0_dp
                    call stop_slide(t0 + xs)
                    exit steps
                end if
                a0 = 0.0_dp
                a1 = 0.0_dp
            end if
            x = 0.0_dp
            as = a0
            events: do nev = 1, max_events + 2 * nt + 1
                if (nev > max_events + 2 * nt) then
                    call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'newmark: too many ' &
                                   //'events in one step near t = '//real_str(t0)//' (a bug)')
                    return
                end if
                h = dt - x
                if (.not. (h > 0.0_dp)) exit events
                if (sliding) then
                    call set_slide(as, a1, h)
                    call ph%taylor(0.0_dp, fa)
                    fa(0) = max(fa(0), 0.0_dp)
                    if (.not. (fa(0) > 0.0_dp)) fa(1) = max(fa(1), 0.0_dp)
                    call ph%taylor(h, fb)
                    m3 = ph%bound(h)
                    call first_zero(ph, h, fa, fb, m3, found, xs, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                    if (.not. found) xs = h
                    ! a segment end before the stop: U rises to it once
                    if (seg < nt) then
                        if (u + ph%disp(xs) >= dd(seg + 1)) then
                            ph%target = dd(seg + 1) - u
                            ph%mode = 1
                            call find_root(ph, 0.0_dp, xs, xb, stat, errmsg, &
                                           fa_known=-ph%target, fb_known=ph%disp(xs) - ph%target)
                            ph%mode = 0
                            if (stat /= SEISPULSE_SUCCESS) return
                            call peak_in(xb)
                            if (stat /= SEISPULSE_SUCCESS) return
                            w = ph%vel(xb)
                            u = dd(seg + 1)
                            seg = seg + 1
                            as = as + (a1 - as) * (xb / h)
                            x = x + xb
                            cycle events
                        end if
                    end if
                    call peak_in(xs)
                    if (stat /= SEISPULSE_SUCCESS) return
                    u = u + ph%disp(xs)
                    if (.not. found) then
                        w = ph%vel(h)
                        exit events
                    end if
                    w = 0.0_dp
                    x = x + xs
                    as = as + (a1 - as) * (xs / h)
                    call stop_slide(t0 + x)
                    ! at rest: the yield stays ky(u) until the next onset
                    cycle events
                end if
                ! at rest from x: onset now, or where a crosses ky_now (linear)
                if (exceeds(as, ky_now)) then
                    call start(t0 + x)
                    cycle events
                end if
                if (.not. exceeds(a1, ky_now)) exit events
                xo = x
                if (a1 > as) xo = x + (dt - x) * (max(ky_now - as, 0.0_dp) / (a1 - as))
                if (.not. (xo < dt)) exit events
                x = max(xo, x)
                as = ky_now
                call start(t0 + x)
            end do events
            if (i <= n - 1) then
                if (want_u) u_hist(i + 1) = u
                if (want_w) w_hist(i + 1) = w * g
                if (i == n - 1 .and. sliding) then
                    ! the run-out: ky >= kmin decelerates it to rest within w/kmin (the count
                    ! in real arithmetic; a longer one: closed form on the last row)
                    rl = w / (kmin * dt)
                    if (rl < real(max_runout, dp)) then
                        lim = n - 1 + ceiling(rl) + 2
                    else
                        closed = .true.
                        lim = n - 1 + max_runout
                    end if
                end if
            end if
        end do steps
        if (sliding) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_values: the run-out ' &
                           //'after the record exceeds '//int_str(max_runout)//' steps ' &
                           //'(a yield too small on a row before the last)')
            return
        end if

        res%final_disp = g * u
        if (want_u) u_hist = g * u_hist
        res%u_max = g * u
        res%u_min = 0.0_dp
        res%max_disp = res%u_max
        call slides_to_si(buf, k, g, res)

    contains

        !> ky at U (g s^2): linear on the segments, constant beyond the last row.
        pure real(dp) function table_ky(uu)
            real(dp), intent(in) :: uu
            table_ky = ky_table_at(uu, dd(1:nt), kv(1:nt))
        end function table_ky

        !> The slide on the current segment from (u, w) with a = aa .. ae over hh.
        subroutine set_slide(aa, ae, hh)
            real(dp), intent(in) :: aa, ae, hh
            ph%kappa = 0.0_dp
            if (seg < nt) ph%kappa = (kv(seg + 1) - kv(seg)) / (dd(seg + 1) - dd(seg))
            ph%w0 = w
            ph%f0 = aa - table_ky(u)
            ph%f1 = (ae - aa) / hh
            ph%mode = 0
        end subroutine set_slide

        subroutine start(t)
            real(dp), intent(in) :: t
            sliding = .true.
            w = 0.0_dp
            wpk = 0.0_dp
            tpk = t
            call append_slide(buf, k, slide_t(direction=1, t_start=t, u_start=u, t_peak=t, &
                                              from_slip=.false.))
        end subroutine start

        subroutine stop_slide(t)
            real(dp), intent(in) :: t
            buf(k)%t_stop = t
            buf(k)%u_stop = u
            buf(k)%w_peak = wpk
            buf(k)%t_peak = tpk
            res%t_end = t
            sliding = .false.
            ky_now = table_ky(u)
        end subroutine stop_slide

        !> The peak speed on a piece of length xx: its interior maxima (the zeros of Y''
        !> from + to -; Y'' solves z'' = -kappa z, first_zero with the bound of |z'''| =
        !> |kappa Y'''|) and its end.
        subroutine peak_in(xx)
            real(dp), intent(in) :: xx
            real(dp) :: ww, xa, za(0:2), zb(0:2), xz
            integer :: j
            logical :: fnd
            xa = 0.0_dp
            ph%mode = 2
            ph%zsign = 1.0_dp
            do j = 1, max_turns
                if (.not. (xx - xa > 0.0_dp)) exit
                ph%x0 = xa
                call ph%taylor(0.0_dp, za)
                if (j == 1 .and. (za(0) < 0.0_dp .or. (.not. (abs(za(0)) > 0.0_dp) &
                                                       .and. za(1) < 0.0_dp))) then
                    ! the speed falls first: the next turn is a minimum
                    ph%zsign = -1.0_dp
                    za = -za
                end if
                za(0) = max(za(0), 0.0_dp)
                if (.not. (za(0) > 0.0_dp)) za(1) = max(za(1), 0.0_dp)
                call ph%taylor(xx - xa, zb)
                call first_zero(ph, xx - xa, za, zb, turn_bound(ph, xx - xa), fnd, xz, stat, &
                                errmsg)
                if (stat /= SEISPULSE_SUCCESS) exit
                if (.not. (fnd .and. xz > 0.0_dp)) exit
                if (ph%zsign > 0.0_dp) then
                    ww = ph%vel(xa + xz)
                    if (ww > wpk) then
                        wpk = ww
                        tpk = t0 + x + xa + xz
                    end if
                end if
                xa = xa + xz
                ph%zsign = -ph%zsign
            end do
            ph%mode = 0
            ph%x0 = 0.0_dp
            ph%zsign = 1.0_dp
            if (stat /= SEISPULSE_SUCCESS) return
            ww = ph%vel(xx)
            if (ww > wpk) then
                wpk = ww
                tpk = t0 + x + xx
            end if
        end subroutine peak_in

    end subroutine rigid_exact_table

    !> f = Y', f' = Y'', f'' = Y''' (mode 0) or f = Y - target (mode 1) of a table slide.
    subroutine table_taylor(self, x, f)
        class(table_slide_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: f(0:2)
        real(dp) :: y, yp, ypp
        y = self%disp(x)
        yp = self%vel(x)
        ypp = -self%kappa * y + self%f0 + self%f1 * x
        if (self%mode == 2) then
            ! f = zsign Y''(x0 + x): Y'''' = -kappa Y''
            y = self%disp(self%x0 + x)
            yp = self%vel(self%x0 + x)
            ypp = -self%kappa * y + self%f0 + self%f1 * (self%x0 + x)
            f(0) = self%zsign * ypp
            f(1) = self%zsign * (-self%kappa * yp + self%f1)
            f(2) = -self%zsign * self%kappa * ypp
        else if (self%mode == 1) then
            f(0) = y - self%target
            f(1) = yp
            f(2) = ypp
        else
            f(0) = yp
            f(1) = ypp
            f(2) = -self%kappa * yp + self%f1
        end if
    end subroutine table_taylor

    !> Y(tau) of (N.8).
    pure real(dp) function table_disp(self, tau)
        class(table_slide_t), intent(in) :: self
        real(dp), intent(in) :: tau
        real(dp) :: c(0:3)
        c = stumpff(self%kappa * tau * tau)
        table_disp = tau * (self%w0 * c(1) + tau * (self%f0 * c(2) + tau * self%f1 * c(3)))
    end function table_disp

    !> Y'(tau) of (N.8).
    pure real(dp) function table_vel(self, tau)
        class(table_slide_t), intent(in) :: self
        real(dp), intent(in) :: tau
        real(dp) :: c(0:3)
        c = stumpff(self%kappa * tau * tau)
        table_vel = self%w0 * c(0) + tau * (self%f0 * c(1) + tau * self%f1 * c(2))
    end function table_vel

    !> Bound on |Y''''| = |kappa Y''| over [0, hh] (N.9): Y'' solves z'' = -kappa z.
    pure real(dp) function table_bound(self, hh)
        class(table_slide_t), intent(in) :: self
        real(dp), intent(in) :: hh
        table_bound = kappa_bound(self%kappa, self%f0, -self%kappa * self%w0 + self%f1, hh)
    end function table_bound

    !> |kappa| max |z| over [0, hh] for z'' = -kappa z, z(0) = z0, z'(0) = z1 (N.9).
    pure real(dp) function kappa_bound(kappa, z0, z1, hh) result(m)
        real(dp), intent(in) :: kappa, z0, z1, hh
        real(dp) :: r
        if (kappa > 0.0_dp) then
            m = kappa * sqrt(z0 * z0 + z1 * z1 / kappa)
        else if (kappa < 0.0_dp) then
            r = sqrt(-kappa)
            m = -kappa * (abs(z0) * cosh(r * hh) + abs(z1) * sinh(r * hh) / r)
        else
            m = 0.0_dp
        end if
        m = m * (1.0_dp + 1.0e-10_dp)
    end function kappa_bound

    !> Bound on |Y'''''| = |kappa Y'''| over [x0, x0 + hh] (mode 2 of table_taylor): Y'''
    !> solves w'' = -kappa w with w = Y''', w' = -kappa Y'' at x0 (as (N.9)).
    function turn_bound(ph, hh) result(m)
        type(table_slide_t), intent(inout) :: ph
        real(dp), intent(in) :: hh
        real(dp) :: m, f(0:2), zs
        zs = ph%zsign
        ph%zsign = 1.0_dp
        call table_taylor(ph, 0.0_dp, f)
        ph%zsign = zs
        m = kappa_bound(ph%kappa, f(1), f(2), hh)
    end function turn_bound

    !> Stumpff functions c_k(z) = sum_j (-z)^j/(2j + k)!, k = 0..3: cos s, sin(s)/s,
    !> (1 - cos s)/s^2, (s - sin s)/s^3 of s = sqrt(z) (cosh, sinh for z < 0); for |z| <= 1 the
    !> series (no cancellation), c_0 = 1 - z c_2 and c_1 = 1 - z c_3.
    pure function stumpff(z) result(c)
        real(dp), intent(in) :: z
        real(dp) :: c(0:3)
        real(dp) :: r
        integer :: j
        if (abs(z) <= 1.0_dp) then
            ! 1/(2j + 2)! and 1/(2j + 3)! for j = 0..8: truncation below 1e-20
            c(2) = 0.0_dp
            c(3) = 0.0_dp
            do j = 8, 0, -1
                c(2) = inv_fact(2 * j + 2) - z * c(2)
                c(3) = inv_fact(2 * j + 3) - z * c(3)
            end do
            c(0) = 1.0_dp - z * c(2)
            c(1) = 1.0_dp - z * c(3)
        else if (z > 0.0_dp) then
            r = sqrt(z)
            c(0) = cos(r)
            c(1) = sin(r) / r
            c(2) = (1.0_dp - c(0)) / z
            c(3) = (1.0_dp - c(1)) / z
        else
            r = sqrt(-z)
            c(0) = cosh(r)
            c(1) = sinh(r) / r
            c(2) = (1.0_dp - c(0)) / z
            c(3) = (1.0_dp - c(1)) / z
        end if
    end function stumpff

    !> First root in (0, h] of z0 + b x + c x^2 (z0 >= 0) when the speed is known to
    !> reach zero by h; the rationalized forms avoid cancellation (no 0/0: the root
    !> exists, so b < 0 or c < 0).
    pure real(dp) function first_root(z0, b, c, h) result(x)
        real(dp), intent(in) :: z0, b, c, h
        real(dp) :: disc
        disc = sqrt(max(b * b - 4.0_dp * c * z0, 0.0_dp))
        if (b <= 0.0_dp) then
            if (-b + disc > 0.0_dp) then
                x = 2.0_dp * z0 / (-b + disc)
            else
                x = 0.0_dp   ! z0 = b = 0 and c <= 0: it stops at once
            end if
        else if (c < 0.0_dp) then
            ! b > 0: the speed grows first, then falls (concave)
            x = (b + disc) / (-2.0_dp * c)
        else
            x = h        ! no root in exact arithmetic: rounding at the step's end
        end if
        x = min(max(x, 0.0_dp), h)
    end function first_root

    ! ------------------------------------------------------------------------------
    ! SLAMMER 1.1's rigid loop
    ! ------------------------------------------------------------------------------

    !> SLAMMER's rigorous rigid-block loop in cm and s (see the module header).
    !> One way: at rest n = sgn(a) if |a| > ky else a/ky, y = a - n ky; sliding y = a - ky;
    !> v = v_prev + dt/2 (y + y_prev), stopped (v = y = 0) when v <= 0. Two ways: the
    !> yield of the direction of motion (or of the sign of a at rest), stopped when v
    !> changes sign or reaches zero. u = u_prev + dt/2 (v + v_prev) K.
    !> With a table (one way): SLAMMER RigidBlock's rule, ky = the first row's at the
    !> start, then after each step interpolated at u (the row index only advances;
    !> constant from the last row on).
    subroutine rigid_slammer(accel, dt, ay_dn, ay_up, k_dn, k_up, one_way, g, res, &
                             u_hist, w_hist, tab_disp, tab_ky)
        real(dp), intent(in) :: accel(:), dt, ay_dn, ay_up, k_dn, k_up, g
        logical, intent(in) :: one_way
        type(newmark_result_t), intent(inout) :: res
        real(dp), intent(out), optional :: u_hist(:), w_hist(:)
        real(dp), intent(in), optional :: tab_disp(:), tab_ky(:)
        integer :: pos, nt

        type(slide_t), allocatable :: buf(:)
        real(dp) :: gcm, t_dn, t_up, a, nn, y, v, r, s, q, u, kf, tr
        integer :: i, nsl, dir, dnew
        logical :: want_u, want_w

        gcm = 100.0_dp * g
        t_dn = ay_dn * gcm
        t_up = ay_up * gcm
        want_u = present(u_hist)
        want_w = present(w_hist)
        allocate(buf(8))
        nsl = 0
        dir = 0
        q = 0.0_dp
        r = 0.0_dp
        s = 0.0_dp
        u = 0.0_dp
        v = 0.0_dp
        pos = 1
        nt = 0
        if (present(tab_disp)) nt = size(tab_disp)
        do i = 1, size(accel)
            a = accel(i) * gcm
            if (one_way) then
                if (v < slammer_rest) then
                    if (abs(a) > t_dn) then
                        nn = sign(1.0_dp, a)
                    else
                        nn = a / t_dn
                    end if
                else
                    nn = 1.0_dp
                end if
                y = a - nn * t_dn
                v = r + 0.5_dp * dt * (y + s)
                if (v <= 0.0_dp) then
                    v = 0.0_dp
                    y = 0.0_dp
                end if
            else
                if (abs(v) < slammer_rest) then
                    if (a > t_dn) then
                        y = a - t_dn
                    else if (-a > t_up) then
                        y = a + t_up
                    else
                        ! inside the yields: a - (a/t) t, zero up to rounding (as SLAMMER)
                        tr = t_dn
                        if (a < 0.0_dp) tr = t_up
                        y = 0.0_dp
                        if (ieee_is_finite(tr)) y = a - (a / tr) * tr
                    end if
                else if (v > 0.0_dp) then
                    y = a - t_dn
                else
                    y = a + t_up
                end if
                v = r + 0.5_dp * dt * (y + s)
                ! SLAMMER: stop unless |r| < 1e-15 or v/r > 0 (no division by r = 0 here)
                if (abs(r) >= slammer_rest) then
                    if (.not. (v / r > 0.0_dp)) then
                        v = 0.0_dp
                        y = 0.0_dp
                    end if
                end if
            end if
            kf = k_dn
            if (v + r < 0.0_dp) kf = k_up
            u = q + 0.5_dp * dt * (v + r) * kf

            ! bookkeeping: the slides, at sample resolution; SLAMMER itself treats
            ! |v| < 1e-15 cm/s (the rounding of a - (a/ky) ky) as rest
            dnew = 0
            if (v >= slammer_rest) dnew = 1
            if (v <= -slammer_rest) dnew = -1
            if (dnew /= dir) then
                if (dir /= 0) call close_slide(i)
                if (dnew /= 0) then
                    call append_slide(buf, nsl, slide_t(direction=dnew, &
                        t_start=real(i - 1, dp) * dt, u_start=q, t_peak=real(i - 1, dp) * dt, &
                        from_slip=dir /= 0))
                end if
                dir = dnew
            end if
            if (dir /= 0) then
                if (abs(v) * kf > buf(nsl)%w_peak) then
                    buf(nsl)%w_peak = abs(v) * kf
                    buf(nsl)%t_peak = real(i - 1, dp) * dt
                end if
            end if
            q = u
            r = v
            s = y
            if (pos < nt) call table_yield()
            if (want_u) u_hist(i) = u / 100.0_dp
            if (want_w) w_hist(i) = v * kf / 100.0_dp
        end do
        if (dir /= 0) call close_slide(size(accel) + 1)
        ! u moves during slides only (and by rounding at rest): extremes at the stops
        res%u_max = max(res%u_max, u)
        res%u_min = min(res%u_min, u)

        res%final_disp = u / 100.0_dp
        res%u_max = res%u_max / 100.0_dp
        res%u_min = res%u_min / 100.0_dp
        res%max_disp = max(res%u_max, -res%u_min)
        deallocate(res%slides)
        allocate(res%slides(nsl))
        do i = 1, nsl
            res%slides(i) = buf(i)
            res%slides(i)%u_start = buf(i)%u_start / 100.0_dp
            res%slides(i)%u_stop = buf(i)%u_stop / 100.0_dp
            res%slides(i)%w_peak = buf(i)%w_peak / 100.0_dp
            res%max_vel = max(res%max_vel, res%slides(i)%w_peak)
        end do

    contains

        !> RigidBlock's update of the yield (cm/s^2) from u (cm) after a step.
        subroutine table_yield()
            real(dp) :: prop
            do while (u > 100.0_dp * tab_disp(pos + 1))
                pos = pos + 1
                if (pos == nt) exit
            end do
            if (pos == nt) then
                t_dn = gcm * tab_ky(nt)
            else
                prop = (u - 100.0_dp * tab_disp(pos)) &
                       / (100.0_dp * tab_disp(pos + 1) - 100.0_dp * tab_disp(pos))
                t_dn = gcm * (tab_ky(pos) - (tab_ky(pos) - tab_ky(pos + 1)) * prop)
            end if
        end subroutine table_yield

        !> The slide ends at sample i (v = 0 there; after the record: still sliding).
        subroutine close_slide(k)
            integer, intent(in) :: k
            buf(nsl)%t_stop = real(min(k, size(accel)) - 1, dp) * dt
            buf(nsl)%u_stop = u
            if (k > size(accel)) buf(nsl)%u_stop = q
            res%t_end = buf(nsl)%t_stop
            res%u_max = max(res%u_max, buf(nsl)%u_stop)
            res%u_min = min(res%u_min, buf(nsl)%u_stop)
        end subroutine close_slide

    end subroutine rigid_slammer

    ! ------------------------------------------------------------------------------
    ! Small helpers
    ! ------------------------------------------------------------------------------

    !> res%slides = buf(1:nsl) with u_start, u_stop, w_peak times g (g s^2 -> m, g s -> m/s)
    !> and max_vel their largest w_peak.
    pure subroutine slides_to_si(buf, nsl, g, res)
        type(slide_t), intent(in) :: buf(:)
        integer, intent(in) :: nsl
        real(dp), intent(in) :: g
        type(newmark_result_t), intent(inout) :: res
        integer :: i
        deallocate(res%slides)
        allocate(res%slides(nsl))
        do i = 1, nsl
            res%slides(i) = buf(i)
            res%slides(i)%u_start = g * buf(i)%u_start
            res%slides(i)%u_stop = g * buf(i)%u_stop
            res%slides(i)%w_peak = g * buf(i)%w_peak
            res%max_vel = max(res%max_vel, res%slides(i)%w_peak)
        end do
    end subroutine slides_to_si

    !> Append a slide to buf(1:nsl), doubling buf when it is full.
    pure subroutine append_slide(buf, nsl, slide)
        type(slide_t), allocatable, intent(inout) :: buf(:)
        integer, intent(inout) :: nsl
        type(slide_t), intent(in) :: slide
        type(slide_t), allocatable :: grown(:)
        if (nsl == size(buf)) then
            allocate(grown(2 * nsl))
            grown(1:nsl) = buf
            call move_alloc(grown, buf)
        end if
        nsl = nsl + 1
        buf(nsl) = slide
    end subroutine append_slide

    !> a exceeds thr by more than rounding (four ulps of the larger): a_g computed at a
    !> stop inside a step is exact only to a few ulps. Safe for thr = +inf.
    elemental logical function exceeds(a, thr)
        real(dp), intent(in) :: a, thr
        exceeds = a - thr > 4.0_dp * epsilon(a) * max(abs(a), abs(thr))
    end function exceeds

    !> An along-plane factor: finite and > 0, unless its direction cannot slide.
    elemental logical function factor_ok(k, ky)
        real(dp), intent(in) :: k, ky
        if (ieee_is_finite(ky)) then
            factor_ok = positive(k) .and. ieee_is_finite(k)
        else
            factor_ok = .not. ieee_is_nan(k)
        end if
    end function factor_ok

end module seispulse_newmark
