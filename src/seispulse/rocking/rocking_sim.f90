!> Nonlinear rocking of a free-standing rigid block (Housner 1963) under any pulse of
!> seispulse_pulses or a sampled accelerogram: uplift, impacts with restitution,
!> overturning; and overturning maps over (frequency, amplitude) grids.
!>
!> Model (doc/rocking.md section 1; the forcing enters with +, so a_g > 0 drives theta > 0):
!>     theta'' = -p^2 [sin(alpha s - theta) - (a_g/g) cos(alpha s - theta)]   Eqs. 2.5/2.6
!>     theta'' =  p^2 [theta + a_g/g - alpha s]                  Eq. 2.7 (`linearized`)
!> with s = +1 while the block pivots on one corner (theta > 0) and s = -1 on the other.
!> From rest it uplifts when a_g > g tan(alpha) (s = +1) or a_g < -g tan(alpha) (s = -1);
!> alpha instead of tan(alpha) in the linearized model (Eq. 2.3). At an impact
!> (theta = 0, doc/rocking.md section 6) the rotation carries on about the other corner, s -> -s,
!> and the angular velocity is multiplied by e (Housner: e = 1 - 1.5 sin^2(alpha) for a
!> uniform rectangle, 1 - (2 m R^2/I_o) sin^2(alpha) for a symmetric body).
!> Vertical ground acceleration a_v (optional; doc/rocking.md section 7): gravity g + a_v,
!>     theta'' = -p^2 [(1 + a_v/g) sin(alpha s - theta) - (a_g/g) cos(alpha s - theta)]  (R.9)
!> with a_v = kv a_g under a pulse (constant uplift thresholds, (R.11)) or a second record
!> (a line on each sample step, so the uplift function (R.10) is a line there).
!>
!> Overturning, as defined here (doc/rocking.md section 3: theta = alpha is only the static limit).
!> - During the excitation the ground may still bring a block back from beyond
!>   |theta| = alpha, so the block has overturned when |theta| reaches pi/2 (it lies on
!>   its side); the same cap in the linearized model keeps every run finite.
!> - Once the excitation is over (a_g = 0 for good) each flight conserves
!>   E = theta'^2/2 + p^2 cos(alpha - |theta|) (linearized: theta'^2/2 + p^2 (alpha |theta|
!>   - theta^2/2)) and an impact can only lower it, so the energy above the top of the
!>   potential, D = theta'^2/2 - 2 p^2 sin^2((alpha - |theta|)/2) (linearized:
!>   theta'^2/2 - p^2 (alpha - |theta|)^2/2), settles the outcome at once: beyond the
!>   barrier (|theta| >= alpha) moving outward, or beyond it with D <= 0: overturns;
!>   inside it with D <= 0: never overturns; inside it moving outward with D > 0:
!>   overturns; otherwise (inward with D > 0) the next impact decides.
!> - A run follows an overturning block to |theta| = pi/2: `t_end` is that time and
!>   `t_overturn` the last outward crossing of |theta| = alpha (the critical time
!>   tau_c of doc/rocking.md section 3). The class counts the impacts before overturning.
!> Rest. When after an impact the next flight would rise less than 1e-10 alpha (the
!> forcing pushing the block back), the block is at rest: this ends a Zeno sequence of
!> impacts (e < 1) in finite time, estimated as the impact time plus tau/(1 - e), tau the
!> flight time 2|theta'|/|theta''(0)| (e = 1: the impact time). With e = 1 a safe block
!> rocks for ever once the excitation is over: without `t_max` the run stops at that
!> decision with ROCK_RUN_TIME_LIMIT.
!>
!> Method. Dormand & Prince 8(5,3) (Hairer's DOP853: stages, error estimator and
!> 7th-order dense output, from seispulse_ode; the flight is its system `flight_ode_t`)
!> with rtol = 1e-12 (absolute scales alpha and p alpha). The
!> time axis is cut into pieces on which a_g is smooth and monotone (the breaks of
!> the pulse and its extrema, each sample step of a record: seispulse_pieces, shared
!> with seispulse_sliding_sim),
!> and every step ends exactly on a piece end, evaluating a_g there as the limit from
!> inside the piece, so the right-hand side is smooth inside each step. While at rest,
!> uplift is the root of a_g -+ g tan(alpha) on a monotone piece (Brent). Impacts,
!> |theta| = pi/2 and the outward crossings of alpha are roots of the dense output of a
!> step (Brent on the polynomial), so events are located to the accuracy of the steps
!> (~1e-12 s in the tests); a step whose angular velocity changes sign is searched at its
!> turning point, and steps are at most 0.5/p long, so an impact cannot hide inside a
!> step (one turning point per step). Each flight integrates the branch s of the
!> equation of motion, continued smoothly past theta = 0, so the root is that of the
!> true motion. No allocation happens in the stepping loops; every loop is bounded
!> (a step budget ends a run with ROCK_RUN_TIME_LIMIT).
module seispulse_rocking_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive, finite_at_least, in_open, in_closed, &
                                check_output_grid
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_optval, only: optval
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_special, only: pi
    use seispulse_ode, only: ode_system, ode_dop853_t, ode_dop853_factor
    use seispulse_pulses, only: pulse_t, pulse_validate, pulse_accel, &
                                exp_consts_t, exp_consts, pulse_kind_name, &
                                PULSE_EXPONENTIAL, PULSE_HALF_SINE, PULSE_SINE_CYCLE, &
                                PULSE_COSINE_CYCLE, PULSE_RECTANGULAR, PULSE_TRIANGULAR, &
                                PULSE_RICKER
    use seispulse_pieces, only: piece_t, piece_iter_t, pulse_pieces_check, record_step_check, &
                                record_pieces_check, record_in_si, pulse_pieces_init, &
                                record_pieces_init, next_piece, exceeds, onset_on_piece, &
                                record_step, piece_step
    implicit none
    private

    public :: rocking_block_t, rocking_run_t
    public :: rectangular_block, symmetric_block, rocking_block_validate
    public :: rock_pulse, rock_record, overturning_map
    public :: ROCK_RUN_REST, ROCK_RUN_NO_UPLIFT, ROCK_RUN_OVERTURN_NO_IMPACT, ROCK_RUN_OVERTURN_ONE_IMPACT, &
              ROCK_RUN_OVERTURN_MANY, ROCK_RUN_TIME_LIMIT

    integer, parameter :: ROCK_RUN_REST = 0                 !! rocked, then came back to rest
    integer, parameter :: ROCK_RUN_NO_UPLIFT = 1            !! never left the ground
    integer, parameter :: ROCK_RUN_OVERTURN_NO_IMPACT = 2   !! overturned without any impact
    integer, parameter :: ROCK_RUN_OVERTURN_ONE_IMPACT = 3  !! overturned after one impact
    integer, parameter :: ROCK_RUN_OVERTURN_MANY = 4        !! overturned after two or more impacts
    integer, parameter :: ROCK_RUN_TIME_LIMIT = 5           !! t_max or the step budget reached first

    !> A rigid block rocking on a rigid base (no sliding, no jumping; doc/rocking.md section 1).
    type :: rocking_block_t
        real(dp) :: alpha = 0.2_dp        !! slenderness angle (rad), 0 < alpha < pi/2
        real(dp) :: p = 2.0_dp            !! frequency parameter (rad/s), p^2 = m g R / I_o
        real(dp) :: e = 0.94_dp           !! restitution, [0, 1]: angular velocity ratio
        real(dp) :: g = 9.80665_dp        !! gravity (m/s^2)
        logical :: linearized = .false.   !! Eq. 2.7 instead of 2.5/2.6
    end type rocking_block_t

    !> Result of a run.
    type :: rocking_run_t
        integer :: outcome = ROCK_RUN_NO_UPLIFT      !! one of the ROCK_* codes
        real(dp) :: t_uplift = 0.0_dp            !! first uplift (s); NaN if none
        real(dp) :: t_overturn = 0.0_dp          !! last outward crossing of |theta| = alpha
                                                 !! before overturning (s); NaN if safe
        integer :: n_impacts = 0                 !! impacts (before overturning, if it does)
        real(dp), allocatable :: t_impacts(:)    !! impact times (s), n_impacts of them
        real(dp) :: theta_max = 0.0_dp           !! largest theta (rad)
        real(dp) :: theta_min = 0.0_dp           !! smallest theta (rad)
        real(dp) :: t_theta_max = 0.0_dp         !! first time theta reaches theta_max (s)
        real(dp) :: t_theta_min = 0.0_dp         !! first time theta reaches theta_min (s)
        real(dp) :: t_end = 0.0_dp               !! rest, |theta| = pi/2, or the limit (s);
                                                 !! 0 without uplift
        integer :: n_steps = 0                   !! integration steps tried (cost)
    end type rocking_run_t

    ! ---- private constants
    real(dp), parameter :: two_pi = 2.0_dp * pi
    real(dp), parameter :: half_pi = 0.5_dp * pi
    !> Default relative tolerance of the steps (absolute: alpha and p alpha times it).
    real(dp), parameter :: rtol_default = 1.0e-12_dp
    !> Smallest and largest accepted rtol.
    real(dp), parameter :: rtol_min = 1.0e-14_dp, rtol_max = 1.0e-3_dp
    !> A flight rising less than this times alpha is rest (see the module notes).
    real(dp), parameter :: rest_tol = 1.0e-10_dp
    !> Step budget of a run (each attempted step counts), and per sample of a record.
    integer, parameter :: max_steps_default = 2000000, steps_per_sample = 40
    !> Step budget of one map cell.
    integer, parameter :: max_steps_map = 200000

    integer, parameter :: GR_ZERO = 0, GR_PULSE = 1, GR_RECORD = 2
    !> Vertical ground acceleration (doc/rocking.md section 7): none, kv a_g, a record.
    integer, parameter :: V_NONE = 0, V_SCALED = 1, V_RECORD = 2
    !> Why `advance` returned.
    integer, parameter :: R_REACHED = 0, R_IMPACT = 1, R_REST = 2, R_CAP = 3, &
                          R_LIMIT = 4, R_TOUCH = 5
    !> Decisions after the excitation.
    integer, parameter :: DEC_OPEN = 0, DEC_SAFE = 1, DEC_OVERTURN = 2

    !> The settings of a run, fixed before it starts.
    type :: sim_t
        real(dp) :: alpha = 0.2_dp       !! slenderness
        real(dp) :: p2 = 4.0_dp          !! p^2
        real(dp) :: p = 2.0_dp
        real(dp) :: e = 1.0_dp           !! restitution
        real(dp) :: inv_g = 1.0_dp       !! 1/g
        real(dp) :: thr_pos = 0.0_dp     !! uplift on side +1 at a_g > thr_pos (m/s^2)
        real(dp) :: thr_neg = 0.0_dp     !! uplift on side -1 at a_g < -thr_neg (m/s^2)
        real(dp) :: tan_u = 0.0_dp       !! tan(alpha), or alpha when linearized (R.10)
        logical :: lin = .false.         !! linearized Eq. 2.7
        real(dp) :: rtol = rtol_default
        real(dp) :: atol(2) = 0.0_dp     !! absolute tolerances of theta and theta'
        real(dp) :: rest_amp = 0.0_dp    !! rest_tol alpha
        logical :: map_mode = .false.    !! stop as soon as the class is known
        logical :: track = .true.        !! impact list, extremes, t_overturn
        logical :: has_t_max = .false.
        real(dp) :: t_max = 0.0_dp       !! end of the run if has_t_max
        integer :: max_steps = max_steps_default
    end type sim_t

    !> Ground acceleration on the current piece, also the function of the uplift roots.
    type, extends(scalar_function) :: ground_t
        integer :: src = GR_ZERO           !! GR_ZERO (no excitation), GR_PULSE, GR_RECORD
        type(pulse_t) :: p                 !! the pulse (GR_PULSE)
        type(exp_consts_t) :: cexp         !! its beta constants (exponential kind)
        real(dp) :: ta = 0.0_dp            !! piece start
        real(dp) :: tb = 0.0_dp            !! piece end
        real(dp) :: ab = 0.0_dp            !! a_g(tb-), the limit from inside the piece
        real(dp) :: a0 = 0.0_dp            !! record step: a_g(ta)
        real(dp) :: slope = 0.0_dp         !! record step: da_g/dt
        real(dp) :: level = 0.0_dp         !! subtracted by eval (uplift threshold)
        integer :: vsrc = V_NONE           !! vertical: V_NONE, V_SCALED (kv a_g), V_RECORD
        real(dp) :: kv = 0.0_dp            !! V_SCALED: a_v = kv a_g
        real(dp) :: vdt = 0.0_dp           !! V_RECORD: sampling interval (s)
        real(dp) :: v0 = 0.0_dp            !! V_RECORD step: a_v(ta) (m/s^2)
        real(dp) :: vslope = 0.0_dp        !! V_RECORD step: da_v/dt (m/s^3)
        real(dp) :: vb = 0.0_dp            !! V_RECORD step: a_v(tb) (m/s^2)
        real(dp) :: vmix = 0.0_dp          !! V_RECORD: eval adds vmix a_v (uplift function)
    contains
        procedure :: eval => ground_eval
    end type ground_t

    !> The flight of the block as a system of seispulse_ode: (theta, theta') on side s.
    type, extends(ode_system) :: flight_ode_t
        type(sim_t) :: sim                 !! settings of the run
        type(ground_t) :: gr               !! ground acceleration on the current piece
        real(dp) :: sa = 0.0_dp            !! alpha s, s = +-1 the side (0 at rest)
    contains
        procedure :: rhs => flight_ode_rhs
    end type flight_ode_t

    !> State of a run, handed to the procedures of the event-driven integrator.
    type :: rocking_state_t
        type(flight_ode_t) :: sys          !! settings, ground, side: the right-hand side
        type(ode_dop853_t) :: ode          !! DOP853 stages and dense output
        real(dp) :: t = 0.0_dp             !! time
        real(dp) :: y(2) = 0.0_dp          !! (theta, theta') at t
        real(dp) :: f(2) = 0.0_dp          !! their derivative at t
        real(dp) :: h = 0.0_dp             !! next step size
        real(dp) :: t_cross = 0.0_dp       !! last outward crossing of |theta| = alpha
        real(dp) :: t_rest = 0.0_dp        !! time the block came back to rest
        real(dp) :: t_lim = 0.0_dp         !! end of the run (t_max or huge)
        integer :: s = 0                   !! side: +1, -1, 0 at rest
        integer :: mode = 0                !! 0 at rest, 1 rocking
        integer :: blocked = 0             !! uplift side ruled out on this piece
        integer :: n_imp = 0               !! impacts so far
        integer :: steps = 0               !! steps tried so far
        integer :: ig = 1                  !! next output grid point
        integer :: ng = 0                  !! grid points
        logical :: from_zero = .false.     !! a flight starts at theta = 0
        logical :: ever_up = .false.       !! the block has uplifted
        logical :: done = .false.          !! the run is over
        real(dp), allocatable :: imp(:)    !! impact times (when tracked)
        real(dp), allocatable :: acc_v(:)  !! vertical record (m/s^2), V_RECORD only
        real(dp), allocatable :: t_grid(:), th_grid(:), om_grid(:)  !! output grid
        integer :: stat = SEISPULSE_SUCCESS              !! event or uplift location failed
        character(len=:), allocatable :: msg             !! its message
    end type rocking_state_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Check a block; the message names the offending component.
    subroutine rocking_block_validate(blk, stat, errmsg)
        type(rocking_block_t), intent(in) :: blk              !! the block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (.not. in_open(blk%alpha, 0.0_dp, half_pi)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = ' &
                           //real_str(blk%alpha)//': must be a number in (0, pi/2) (rad)')
        else if (.not. finite_positive(blk%p)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'p = '//real_str(blk%p) &
                           //': must be a finite number > 0 (rad/s)')
        else if (.not. in_closed(blk%e, 0.0_dp, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'e = '//real_str(blk%e) &
                           //': the coefficient of restitution must be in [0, 1]')
        else if (.not. finite_positive(blk%g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(blk%g) &
                           //': must be a finite number > 0 (m/s^2)')
        end if
    end subroutine rocking_block_validate

    !> Uniform rectangular block of half-width b and half-height h (doc/rocking.md section 1):
    !> R = sqrt(b^2 + h^2), alpha = atan(b/h), I_o = (4/3) m R^2 so p = sqrt(3 g/(4 R)),
    !> and Housner's restitution e = max(0, 1 - 1.5 sin^2(alpha)) (doc/rocking.md section 6; 0 for
    !> squat blocks, b/h > sqrt 2; change blk%e afterwards for another value).
    !> g is optional (default STANDARD_GRAVITY, as Python's `rocking.rectangular_block`);
    !> when omitted, pass blk and stat by keyword.
    subroutine rectangular_block(b, h, g, blk, stat, errmsg)
        real(dp), intent(in) :: b                             !! half-width (m), > 0
        real(dp), intent(in) :: h                             !! half-height (m), > 0
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        type(rocking_block_t), intent(out) :: blk             !! the block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: g_in
        g_in = optval(g, STANDARD_GRAVITY)
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(b)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'b = '//real_str(b) &
                           //': the half-width must be a finite number > 0 (m)')
        else if (.not. finite_positive(h)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'h = '//real_str(h) &
                           //': the half-height must be a finite number > 0 (m)')
        else if (.not. finite_positive(g_in)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g_in) &
                           //': must be a finite number > 0 (m/s^2)')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        ! the symmetric body with I_o = (4/3) m R^2: one formula for p and e (and the
        ! floor e >= 0 of squat blocks, b/h > sqrt 2)
        call symmetric_block(hypot(b, h), atan2(b, h), 4.0_dp / 3.0_dp, g_in, blk, stat, errmsg)
    end subroutine rectangular_block

    !> Block symmetric about the vertical through its centre of mass (doc/rocking.md section 1):
    !> R from the pivot corner to the centre of mass, slenderness alpha, and
    !> I_o = io_over_mr2 m R^2 about the corner (>= m R^2; 4/3 for a uniform rectangle).
    !> p = sqrt(g/(io_over_mr2 R)) and Housner's e = 1 - (2/io_over_mr2) sin^2(alpha)
    !> (angular momentum about the new corner, doc/rocking.md section 6), set to 0 where the formula
    !> is negative (squat bodies: the impact then stops the rocking).
    !> g is optional (default STANDARD_GRAVITY, as Python's `rocking.symmetric_block`);
    !> when omitted, pass blk and stat by keyword.
    subroutine symmetric_block(r, alpha, io_over_mr2, g, blk, stat, errmsg)
        real(dp), intent(in) :: r                             !! pivot to centre of mass (m), > 0
        real(dp), intent(in) :: alpha                         !! slenderness (rad), in (0, pi/2)
        real(dp), intent(in) :: io_over_mr2                   !! I_o/(m R^2), finite, >= 1
        !> gravity (m/s^2), > 0; default STANDARD_GRAVITY (9.80665 m/s^2)
        real(dp), intent(in), optional :: g
        type(rocking_block_t), intent(out) :: blk             !! the block
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: g_in
        g_in = optval(g, STANDARD_GRAVITY)
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(r)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'r = '//real_str(r) &
                           //': must be a finite number > 0 (m)')
        else if (.not. in_open(alpha, 0.0_dp, half_pi)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = ' &
                           //real_str(alpha)//': must be a number in (0, pi/2) (rad)')
        else if (.not. finite_at_least(io_over_mr2, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'io_over_mr2 = ' &
                           //real_str(io_over_mr2)//': I_o/(m R^2) must be a finite number' &
                           //' >= 1 (I_o = I_cm + m R^2)')
        else if (.not. finite_positive(g_in)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g_in) &
                           //': must be a finite number > 0 (m/s^2)')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        blk%alpha = alpha
        blk%p = sqrt(g_in / (io_over_mr2 * r))
        blk%e = max(0.0_dp, 1.0_dp - (2.0_dp / io_over_mr2) * sin(alpha)**2)
        blk%g = g_in
        blk%linearized = .false.
    end subroutine symmetric_block

    !> Rocking response to a pulse of seispulse_pulses (SI units), from rest or from the
    !> initial state (theta0, omega0) at t = 0, until rest, overturning or the limit.
    !>
    !> Optional output grid: `t_grid`, `theta_grid`, `omega_grid` all present or all
    !> absent, of one size, `t_grid` finite and ascending (any times: the initial state
    !> at t <= 0, 0 while at rest, the dense output of the steps while rocking,
    !> +-pi/2 and 0 after overturning, NaN after a time limit). The spike (beta = +inf)
    !> exceeds any threshold at one instant only: the block never uplifts. Ricker
    !> wavelets end at pi f_p (t - t0) = 10 (|a_g| < 1e-40 a_p) and M&P pulses need
    !> gamma <= 1e6, as in seispulse_sliding_sim.
    !>
    !> Optional vertical ground acceleration (doc/rocking.md section 7): a_v = kv a_g
    !> (m/s^2, positive up), the same pulse scaled; kv finite, and g + kv a_g >= 0 at every
    !> instant (checked at the ends of the monotone pieces, where a_g has its extremes).
    subroutine rock_pulse(blk, p, run, stat, errmsg, t_grid, theta_grid, omega_grid, t_max, &
                          theta0, omega0, rtol, kv)
        type(rocking_block_t), intent(in) :: blk              !! the block
        type(pulse_t), intent(in) :: p                        !! ground acceleration pulse (SI)
        type(rocking_run_t), intent(out) :: run               !! the result
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> output times (s), ascending; absent: no history (with theta_grid, omega_grid)
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: theta_grid(:)      !! theta at t_grid (rad)
        real(dp), intent(out), optional :: omega_grid(:)      !! theta' at t_grid (rad/s)
        !> end of the run (s), > 0; absent: until rest, overturning or the step budget
        real(dp), intent(in), optional :: t_max
        !> initial theta (rad), |.| < pi/2; default 0 (at rest)
        real(dp), intent(in), optional :: theta0
        real(dp), intent(in), optional :: omega0              !! initial theta' (rad/s); default 0
        real(dp), intent(in), optional :: rtol                !! step tolerance (default 1e-12)
        real(dp), intent(in), optional :: kv                  !! a_v/a_g (1), default 0
        type(rocking_state_t) :: st
        type(piece_iter_t) :: it
        real(dp) :: th0, om0, no_record(0), a_bad, t_bad
        logical :: bad

        call empty_run(run)
        call rocking_block_validate(blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call pulse_pieces_check(p, 'rocking', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_options(t_grid, theta_grid, omega_grid, t_max, theta0, omega0, rtol, &
                           th0, om0, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_kv(kv, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(kv)) then
            call kv_floor(p, kv, blk%g, bad, a_bad, t_bad, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (bad) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kv = '//real_str(kv) &
                               //': the vertical acceleration kv a_g = '//real_str(a_bad) &
                               //' m/s^2 at t = '//real_str(t_bad)//' s is below -g = ' &
                               //real_str(-blk%g)//' m/s^2 (the block would leave the ground)')
                return
            end if
        end if
        call setup_sim(blk, st%sys%sim, t_max, rtol, kv)
        if (present(kv)) call set_kv(st%sys%gr, kv)
        st%sys%gr%src = GR_PULSE
        st%sys%gr%p = p
        if (p%kind == PULSE_EXPONENTIAL) st%sys%gr%cexp = exp_consts(p%beta)
        call pulse_pieces_init(it, p)
        call simulate(st, it, no_record, th0, om0, run, stat, errmsg, t_grid, theta_grid, &
                      omega_grid)
    end subroutine rock_pulse

    !> Rocking response to an accelerogram: accel(i) (g) at t = (i - 1) dt, linear in
    !> between, a_g = 0 after the last sample (a jump if it is not 0). The samples are
    !> taken to m/s^2 as g * accel(i) (`g`: the unit of the record, usually blk%g; the
    !> block's own blk%g sets the uplift threshold and the equation of motion; a record
    !> already in m/s^2 is one in units of g = 1 m/s^2, taken as it is). Everything else
    !> as `rock_pulse`; the step budget grows with the record (40 per sample).
    !>
    !> Optional vertical record `accel_v` (g, positive up; doc/rocking.md section 7): same dt
    !> and size as accel, linear in between, 0 after the last sample, taken to m/s^2 as
    !> g * accel_v(i); every sample must keep blk%g + g accel_v(i) >= 0.
    subroutine rock_record(blk, accel, dt, g, run, stat, errmsg, t_grid, theta_grid, &
                           omega_grid, t_max, theta0, omega0, rtol, accel_v)
        type(rocking_block_t), intent(in) :: blk              !! the block
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g), finite
        real(dp), intent(in) :: dt                            !! sampling interval (s), > 0
        real(dp), intent(in) :: g                             !! the unit g of accel (m/s^2), > 0
        type(rocking_run_t), intent(out) :: run               !! the result
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> output times (s), ascending; absent: no history (with theta_grid, omega_grid)
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: theta_grid(:)      !! theta at t_grid (rad)
        real(dp), intent(out), optional :: omega_grid(:)      !! theta' at t_grid (rad/s)
        !> end of the run (s), > 0; absent: until rest, overturning or the step budget
        real(dp), intent(in), optional :: t_max
        !> initial theta (rad), |.| < pi/2; default 0 (at rest)
        real(dp), intent(in), optional :: theta0
        real(dp), intent(in), optional :: omega0              !! initial theta' (rad/s); default 0
        real(dp), intent(in), optional :: rtol                !! step tolerance (default 1e-12)
        !> vertical acceleration (g), finite; absent: none
        real(dp), intent(in), optional :: accel_v(:)
        type(rocking_state_t) :: st
        type(piece_iter_t) :: it
        real(dp) :: th0, om0
        real(dp), allocatable :: accel_si(:)
        integer :: i

        call empty_run(run)
        call rocking_block_validate(blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call record_step_check(accel, dt, g, stat, errmsg)   ! dt, g; not empty, finite
        if (stat /= SEISPULSE_SUCCESS) return
        call check_options(t_grid, theta_grid, omega_grid, t_max, theta0, omega0, rtol, &
                           th0, om0, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        ! the samples in m/s^2 (g = 1: the very same numbers)
        call record_in_si(accel, g, accel_si, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(accel_v)) then
            if (size(accel_v) /= size(accel)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel_v: '//int_str( &
                               size(accel_v))//' samples: must have as many as accel (' &
                               //int_str(size(accel))//'), at the same dt')
                return
            end if
            ! finite samples, g accel_v(i) finite (dt and g checked above with accel)
            call record_pieces_check(accel_v, stat, errmsg, name='accel_v')
            if (stat /= SEISPULSE_SUCCESS) return
            call record_in_si(accel_v, g, st%acc_v, stat, errmsg, name='accel_v')
            if (stat /= SEISPULSE_SUCCESS) return
            do i = 1, size(accel_v)
                if (st%acc_v(i) < -blk%g) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel_v(' &
                                   //int_str(i)//') = '//real_str(accel_v(i))//' at t = ' &
                                   //real_str(real(i - 1, dp) * dt)//' s: g + a_v < 0 (g = ' &
                                   //real_str(blk%g)//' m/s^2; the block would leave the' &
                                   //' ground)')
                    return
                end if
            end do
        end if
        call setup_sim(blk, st%sys%sim, t_max, rtol)
        if (present(accel_v)) then
            st%sys%gr%vsrc = V_RECORD
            st%sys%gr%vdt = dt
        end if
        if (real(steps_per_sample, dp) * size(accel) > real(huge(1) - max_steps_default, dp)) then
            st%sys%sim%max_steps = huge(1)
        else
            st%sys%sim%max_steps = max_steps_default + steps_per_sample * size(accel)
        end if
        st%sys%gr%src = GR_RECORD
        call record_pieces_init(it, size(accel), dt)
        call simulate(st, it, accel_si, th0, om0, run, stat, errmsg, t_grid, theta_grid, &
                      omega_grid)
    end subroutine rock_record

    !> Overturning map of a pulse family: classes(i, j) for amp_ratio(i) = a_p/(g tan alpha)
    !> and freq_ratio(j) = omega_p/p: 0 safe, 1 overturns without impact, 2 after one
    !> impact, 3 after more (-1: undecided within the step budget, not expected), from the
    !> integrator of `rock_pulse` (nonlinear, or Eq. 2.7 with `linearized`; the amplitude
    !> is scaled by g tan(alpha) in both). The map is dimensionless: p = 1 rad/s, g = 1.
    !> Time scale: omega_p = 2 pi/T_p with T_p the pulse duration (sine_cycle and
    !> cosine_cycle: the period of one cycle; half_sine, rectangular, triangular: the pulse
    !> length; exponential: t_d, so f = p t_d = 2 pi/freq_ratio) and, for the Ricker wavelet,
    !> omega_p = 2 pi f_p. `template` supplies beta and full (exponential), peak_frac
    !> (triangular), cycles (sine_cycle, cosine_cycle: n cycles of T_p each, default 1) and,
    !> for the Ricker wavelet, the centre in periods, t0 f_p (default 1.5); its amplitude
    !> and time scale are ignored. Each cell stops as soon as its class is known (at most
    !> one impact after the end of the pulse). Optional vertical ground acceleration
    !> a_v = kv a_g in every cell (doc/rocking.md section 7); a cell whose kv a_g goes below
    !> -g is an error naming kv and its amp_ratio.
    subroutine overturning_map(alpha, e, kind, freq_ratio, amp_ratio, classes, stat, errmsg, &
                               linearized, template, rtol, kv)
        real(dp), intent(in) :: alpha                         !! slenderness (rad), in (0, pi/2)
        real(dp), intent(in) :: e                             !! coefficient of restitution, [0, 1]
        integer, intent(in) :: kind                           !! PULSE_* code (not PULSE_MP)
        real(dp), intent(in) :: freq_ratio(:)                 !! omega_p/p, finite, > 0
        real(dp), intent(in) :: amp_ratio(:)                  !! a_p/(g tan alpha), finite, >= 0
        integer, intent(out) :: classes(:, :)                 !! size(amp_ratio) x size(freq_ratio)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        logical, intent(in), optional :: linearized           !! Eq. 2.7 (default .false.)
        !> shape parameters of the kind; absent: pulse_t defaults
        type(pulse_t), intent(in), optional :: template
        real(dp), intent(in), optional :: rtol                !! step tolerance (default 1e-12)
        real(dp), intent(in), optional :: kv                  !! a_v/a_g (1), default 0
        type(rocking_block_t) :: blk
        type(rocking_state_t) :: st
        type(piece_iter_t) :: it
        type(pulse_t) :: pl
        type(rocking_run_t) :: run
        real(dp) :: no_record(0), tan_a, t0f, a_bad, t_bad
        integer :: i, j
        logical :: bad
        character(len=24) :: idx

        classes = -1
        blk%alpha = alpha
        blk%e = e
        blk%p = 1.0_dp
        blk%g = 1.0_dp
        if (present(linearized)) blk%linearized = linearized
        call rocking_block_validate(blk, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        select case (kind)
        case (PULSE_EXPONENTIAL, PULSE_HALF_SINE, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, &
              PULSE_RECTANGULAR, PULSE_TRIANGULAR, PULSE_RICKER)
        case default
            write(idx, '(i0)') kind
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kind = '//trim(idx) &
                           //' ('//pulse_kind_name(kind)//'): maps take an acceleration' &
                           //' pulse with a time scale: exponential, half_sine, sine_cycle,' &
                           //' cosine_cycle, rectangular, triangular or ricker')
            return
        end select
        if (size(classes, 1) /= size(amp_ratio) .or. size(classes, 2) /= size(freq_ratio)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'classes: must be ' &
                           //'size(amp_ratio) x size(freq_ratio)')
            return
        end if
        do j = 1, size(freq_ratio)
            if (.not. finite_positive(freq_ratio(j))) then
                write(idx, '(i0)') j
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'freq_ratio(' &
                               //trim(idx)//') = '//real_str(freq_ratio(j)) &
                               //': must be a finite number > 0')
                return
            end if
        end do
        do i = 1, size(amp_ratio)
            if (.not. finite_at_least(amp_ratio(i), 0.0_dp)) then
                write(idx, '(i0)') i
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'amp_ratio(' &
                               //trim(idx)//') = '//real_str(amp_ratio(i)) &
                               //': must be a finite number >= 0')
                return
            end if
        end do
        if (present(rtol)) then
            if (.not. in_closed(rtol, rtol_min, rtol_max)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'rtol = ' &
                               //real_str(rtol)//': must be in [1e-14, 1e-3]')
                return
            end if
        end if
        call check_kv(kv, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(template)) pl = template
        pl%kind = kind
        t0f = 1.5_dp
        if (present(template)) t0f = template%t0 * template%freq
        if (kind == PULSE_RICKER .and. .not. finite_at_least(t0f, 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't0 = '//real_str(t0f) &
                           //': template%t0 * template%freq must be a finite number >= 0')
            return
        end if
        call setup_sim(blk, st%sys%sim, rtol=rtol, kv=kv)
        if (present(kv)) call set_kv(st%sys%gr, kv)
        st%sys%sim%map_mode = .true.
        st%sys%sim%track = .false.
        st%sys%sim%max_steps = max_steps_map
        tan_a = tan(alpha)
        if (kind == PULSE_EXPONENTIAL) st%sys%gr%cexp = exp_consts(pl%beta)

        do j = 1, size(freq_ratio)
            if (kind == PULSE_RICKER) then
                pl%freq = freq_ratio(j) / two_pi
                pl%t0 = t0f / pl%freq
            else
                pl%duration = two_pi / freq_ratio(j)
            end if
            do i = 1, size(amp_ratio)
                pl%amp = amp_ratio(i) * tan_a
                if (i == 1) then
                    call pulse_validate(pl, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                end if
                if (st%sys%gr%vsrc /= V_NONE) then
                    call kv_floor(pl, kv, 1.0_dp, bad, a_bad, t_bad, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                    if (bad) then
                        write(idx, '(i0)') i
                        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kv = ' &
                                       //real_str(kv)//', amp_ratio('//trim(idx)//') = ' &
                                       //real_str(amp_ratio(i))//': kv a_g reaches ' &
                                       //real_str(a_bad)//' g, below -g (the block would' &
                                       //' leave the ground)')
                        return
                    end if
                end if
                st%sys%gr%src = GR_PULSE
                st%sys%gr%p = pl
                call pulse_pieces_init(it, pl)
                call simulate(st, it, no_record, 0.0_dp, 0.0_dp, run, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                select case (run%outcome)
                case (ROCK_RUN_REST, ROCK_RUN_NO_UPLIFT)
                    classes(i, j) = 0
                case (ROCK_RUN_OVERTURN_NO_IMPACT)
                    classes(i, j) = 1
                case (ROCK_RUN_OVERTURN_ONE_IMPACT)
                    classes(i, j) = 2
                case (ROCK_RUN_OVERTURN_MANY)
                    classes(i, j) = 3
                case default
                    classes(i, j) = -1
                end select
            end do
        end do
    end subroutine overturning_map

    ! ------------------------------------------------------------------------------
    ! Set-up
    ! ------------------------------------------------------------------------------

    !> Settings of a run from a (valid) block.
    subroutine setup_sim(blk, sim, t_max, rtol, kv)
        type(rocking_block_t), intent(in) :: blk
        type(sim_t), intent(out) :: sim
        real(dp), intent(in), optional :: t_max
        real(dp), intent(in), optional :: rtol
        real(dp), intent(in), optional :: kv     !! a_v = kv a_g (finite; default 0)
        real(dp) :: k
        sim%alpha = blk%alpha
        sim%p = blk%p
        sim%p2 = blk%p * blk%p
        sim%e = blk%e
        sim%inv_g = 1.0_dp / blk%g
        sim%lin = blk%linearized
        ! uplift at |a_g| > g tan(alpha), or g alpha in the linearized model (Eq. 2.3);
        ! with a_v = kv a_g at a_g > g tan(alpha)/(1 - kv tan(alpha)) on side +1 and
        ! a_g < -g tan(alpha)/(1 + kv tan(alpha)) on side -1, never where the denominator
        ! is <= 0 (doc/rocking.md (R.11); kv = 0: the thresholds g tan(alpha) bit for bit)
        if (sim%lin) then
            sim%tan_u = blk%alpha
        else
            sim%tan_u = tan(blk%alpha)
        end if
        k = 0.0_dp
        if (present(kv)) k = kv
        sim%thr_pos = huge(1.0_dp)
        sim%thr_neg = huge(1.0_dp)
        if (k * sim%tan_u < 1.0_dp) sim%thr_pos = blk%g * sim%tan_u / (1.0_dp - k * sim%tan_u)
        if (1.0_dp + k * sim%tan_u > 0.0_dp) &
            sim%thr_neg = blk%g * sim%tan_u / (1.0_dp + k * sim%tan_u)
        sim%rtol = rtol_default
        if (present(rtol)) sim%rtol = rtol
        sim%atol = sim%rtol * [blk%alpha, blk%p * blk%alpha]
        sim%rest_amp = rest_tol * blk%alpha
        sim%has_t_max = .false.
        if (present(t_max)) then
            if (t_max <= huge(t_max)) then
                sim%has_t_max = .true.
                sim%t_max = t_max
            end if
        end if
    end subroutine setup_sim

    !> Vertical ground acceleration a_v = kv a_g on gr (kv = 0: none, the horizontal path).
    pure subroutine set_kv(gr, kv)
        type(ground_t), intent(inout) :: gr
        real(dp), intent(in) :: kv
        if (abs(kv) > 0.0_dp) then
            gr%vsrc = V_SCALED
            gr%kv = kv
        end if
    end subroutine set_kv

    !> kv, when given, is a finite number.
    subroutine check_kv(kv, stat, errmsg)
        real(dp), intent(in), optional :: kv
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. present(kv)) return
        if (.not. ieee_is_finite(kv)) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
            'kv = '//real_str(kv)//': must be a finite number (a_v = kv a_g)')
    end subroutine check_kv

    !> Does kv a_g go below -g anywhere under the (valid) pulse p? The pieces are monotone,
    !> so a_g has its extremes at their ends (limits from inside): bad, with the lowest
    !> kv a_g (m/s^2) and its time (s).
    subroutine kv_floor(p, kv, g, bad, a_low, t_low, stat, errmsg)
        type(pulse_t), intent(in) :: p
        real(dp), intent(in) :: kv, g
        logical, intent(out) :: bad
        real(dp), intent(out) :: a_low, t_low
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(piece_iter_t) :: it
        type(piece_t) :: piece
        real(dp) :: no_record(0)
        integer :: k
        logical :: found
        bad = .false.
        a_low = 0.0_dp
        t_low = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (.not. abs(kv) > 0.0_dp) return
        call pulse_pieces_init(it, p)
        do k = 1, huge(k) - 1   ! next_piece ends the list
            call next_piece(it, no_record, 'rocking', piece, found, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS .or. .not. found) exit
            if (kv * piece%aa < a_low) then
                a_low = kv * piece%aa
                t_low = piece%ta
            end if
            if (kv * piece%ab < a_low) then
                a_low = kv * piece%ab
                t_low = piece%tb
            end if
        end do
        bad = a_low < -g
    end subroutine kv_floor

    !> Checks shared by rock_pulse and rock_record; th0, om0 receive the initial state.
    subroutine check_options(t_grid, theta_grid, omega_grid, t_max, theta0, omega0, rtol, &
                             th0, om0, stat, errmsg)
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(in), optional :: theta_grid(:)
        real(dp), intent(in), optional :: omega_grid(:)
        real(dp), intent(in), optional :: t_max
        real(dp), intent(in), optional :: theta0
        real(dp), intent(in), optional :: omega0
        real(dp), intent(in), optional :: rtol
        real(dp), intent(out) :: th0, om0
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        th0 = 0.0_dp
        om0 = 0.0_dp
        if (present(t_max)) then
            if (ieee_is_nan(t_max)) then
                stat = SEISPULSE_INVALID_INPUT
            else if (.not. t_max > 0.0_dp) then
                stat = SEISPULSE_INVALID_INPUT
            end if
            if (stat /= SEISPULSE_SUCCESS) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_max = ' &
                               //real_str(t_max)//': must be a number > 0 (s) or +inf')
                return
            end if
        end if
        if (present(theta0)) then
            if (.not. in_open(theta0, -half_pi, half_pi)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta0 = ' &
                               //real_str(theta0)//': must be a number in (-pi/2, pi/2) (rad)')
                return
            end if
            th0 = theta0
        end if
        if (present(omega0)) then
            if (.not. ieee_is_finite(omega0)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'omega0 = ' &
                               //real_str(omega0)//': must be a finite number (rad/s)')
                return
            end if
            om0 = omega0
        end if
        if (present(rtol)) then
            if (.not. in_closed(rtol, rtol_min, rtol_max)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'rtol = ' &
                               //real_str(rtol)//': must be in [1e-14, 1e-3]')
                return
            end if
        end if
        call check_output_grid('theta_grid', 'omega_grid', stat, errmsg, t_grid, theta_grid, &
                               omega_grid)
    end subroutine check_options

    !> A well-defined result for the error returns.
    subroutine empty_run(run)
        type(rocking_run_t), intent(inout) :: run
        if (allocated(run%t_impacts)) deallocate(run%t_impacts)
        allocate(run%t_impacts(0))
        run%outcome = ROCK_RUN_NO_UPLIFT
        run%t_uplift = ieee_value(run%t_uplift, ieee_quiet_nan)
        run%t_overturn = ieee_value(run%t_overturn, ieee_quiet_nan)
        run%n_impacts = 0
        run%theta_max = 0.0_dp
        run%theta_min = 0.0_dp
        run%t_theta_max = 0.0_dp
        run%t_theta_min = 0.0_dp
        run%t_end = 0.0_dp
        run%n_steps = 0
    end subroutine empty_run

    ! ------------------------------------------------------------------------------
    ! The event-driven integrator
    ! ------------------------------------------------------------------------------

    !> Run the block over the pieces of `it` (settings st%sys%sim, ground st%sys%gr,
    !> samples `accel`), then in free motion until the outcome is known (map mode) or the
    !> run ends. `st` keeps its integrator between calls (one allocation for a map).
    subroutine simulate(st, it, accel, th0, om0, run, stat, errmsg, t_grid, th_grid, om_grid)
        type(rocking_state_t), intent(inout) :: st
        type(piece_iter_t), intent(inout) :: it
        real(dp), intent(in) :: accel(:)
        real(dp), intent(in) :: th0, om0
        type(rocking_run_t), intent(inout) :: run
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: th_grid(:)
        real(dp), intent(out), optional :: om_grid(:)

        call st%ode%init(2, st%sys%sim%rtol, st%sys%sim%atol, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        st%ng = 0
        if (present(t_grid)) then
            st%ng = size(t_grid)
            if (allocated(st%t_grid)) deallocate(st%t_grid, st%th_grid, st%om_grid)
            allocate(st%t_grid, source=t_grid)
            allocate(st%th_grid(st%ng), st%om_grid(st%ng))
        end if
        st%stat = SEISPULSE_SUCCESS
        call simulate_run(st, it, accel, th0, om0, run, stat, errmsg)
        if (stat == SEISPULSE_SUCCESS .and. st%stat /= SEISPULSE_SUCCESS) &
            call set_error(stat, errmsg, st%stat, st%msg)
        if (present(t_grid)) then
            th_grid(:) = st%th_grid
            om_grid(:) = st%om_grid
        end if
    end subroutine simulate

    !> The body of `simulate`: errors of the pieces in stat, of the event location in
    !> st%stat.
    subroutine simulate_run(st, it, accel, th0, om0, run, stat, errmsg)
        type(rocking_state_t), intent(inout) :: st
        type(piece_iter_t), intent(inout) :: it
        real(dp), intent(in) :: accel(:)
        real(dp), intent(in) :: th0, om0
        type(rocking_run_t), intent(inout) :: run
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(piece_t) :: piece
        integer :: reason, dec, k, src_saved
        logical :: found

        stat = SEISPULSE_SUCCESS
        associate(sim => st%sys%sim, gr => st%sys%gr)
        st%ig = 1
        st%t = 0.0_dp
        st%y = [th0, om0]
        st%f = 0.0_dp
        st%n_imp = 0
        st%steps = 0
        st%done = .false.
        st%blocked = 0
        st%t_cross = ieee_value(st%t_cross, ieee_quiet_nan)
        run%t_overturn = st%t_cross
        st%t_rest = 0.0_dp
        st%t_lim = huge(st%t_lim)
        if (sim%has_t_max) st%t_lim = sim%t_max
        ! first step: a small fraction of the block's time scale; the control adapts it
        st%h = 0.05_dp / sim%p
        run%theta_max = max(0.0_dp, th0)
        run%theta_min = min(0.0_dp, th0)
        run%t_theta_max = 0.0_dp
        run%t_theta_min = 0.0_dp
        if (sim%track .and. .not. allocated(st%imp)) allocate(st%imp(16))
        ! the state before t = 0 is the initial one
        do while (st%ig <= st%ng)
            if (st%t_grid(st%ig) > 0.0_dp) exit
            st%th_grid(st%ig) = th0
            st%om_grid(st%ig) = om0
            st%ig = st%ig + 1
        end do
        if (abs(th0) > 0.0_dp .or. abs(om0) > 0.0_dp) then
            st%mode = 1
            if (abs(th0) > 0.0_dp) then
                st%s = int(sign(1.0_dp, th0))
            else
                st%s = int(sign(1.0_dp, om0))
            end if
            st%ever_up = .true.
            run%t_uplift = 0.0_dp
            st%from_zero = .not. abs(th0) > 0.0_dp
            ! an initial state beyond the barrier has no crossing: count it from t = 0
            if (abs(th0) >= sim%alpha) st%t_cross = 0.0_dp
        else
            st%mode = 0
            st%s = 0
            st%ever_up = .false.
            st%from_zero = .false.
            run%t_uplift = ieee_value(run%t_uplift, ieee_quiet_nan)
        end if
        st%sys%sa = sim%alpha * real(st%s, dp)

        pieces: do
            call next_piece(it, accel, 'rocking', piece, found, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (.not. found) exit pieces
            call load_piece(gr, piece)
            if (gr%vsrc == V_RECORD) call load_vert(gr, record_step(st%acc_v, piece_step(it), &
                                                                     gr%vdt))
            if (st%t < piece%ta) then
                ! no excitation before this piece (M&P window): free flight or rest
                if (st%mode == 1) then
                    src_saved = gr%src
                    gr%src = GR_ZERO
                    call run_segment(st, run, piece%ta)
                    gr%src = src_saved
                    if (st%done) return
                end if
                if (st%t < piece%ta) then
                    call fill_rest(st, piece%ta)
                    st%t = piece%ta
                end if
            end if
            st%blocked = 0
            call run_segment(st, run, piece%tb)
            if (st%done) return
        end do pieces

        ! the excitation is over: a_g = 0 from now on
        gr%src = GR_ZERO
        if (st%mode == 0) then
            call finish_rest(st, run)
            return
        end if
        free: do k = 1, sim%max_steps
            dec = decide(sim, st%y, st%s)
            if (sim%map_mode .and. dec /= DEC_OPEN) then
                if (dec == DEC_SAFE) then
                    call finish(st, run, ROCK_RUN_REST)
                else
                    call finish_overturn(st, run)
                end if
                return
            end if
            if (dec == DEC_SAFE) then
                if (.not. (sim%has_t_max .or. sim%e < 1.0_dp)) then
                    ! e = 1: perpetual rocking, nothing more to learn without t_max
                    call finish(st, run, ROCK_RUN_TIME_LIMIT)
                    return
                end if
                call advance(st, run, st%t_lim, .false., reason)
            else
                call advance(st, run, st%t_lim, .true., reason)
            end if
            if (st%stat /= SEISPULSE_SUCCESS) return
            select case (reason)
            case (R_IMPACT)
                cycle free
            case (R_REST, R_TOUCH)
                call finish_rest(st, run)
            case (R_CAP)
                call finish_overturn(st, run)
            case default
                call finish(st, run, ROCK_RUN_TIME_LIMIT)
            end select
            return
        end do free
        call finish(st, run, ROCK_RUN_TIME_LIMIT)
        end associate
    end subroutine simulate_run

    !> Rest and flights on the current piece up to t_stop.
    subroutine run_segment(st, run, t_stop)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        integer :: kk, reason
        do kk = 1, st%sys%sim%max_steps
            if (.not. st%t < t_stop) return
            if (.not. st%t < st%t_lim) then
                call finish(st, run, ROCK_RUN_TIME_LIMIT)
                return
            end if
            if (st%mode == 0) then
                call rest_scan(st, run, t_stop)
                if (st%done .or. st%stat /= SEISPULSE_SUCCESS) then
                    st%done = .true.
                    return
                end if
            else
                call advance(st, run, min(t_stop, st%t_lim), .false., reason)
                if (st%stat /= SEISPULSE_SUCCESS) then
                    st%done = .true.
                    return
                end if
                select case (reason)
                case (R_TOUCH)
                    ! the threshold was touched, not exceeded: no uplift that way
                    ! on this monotone piece
                    st%blocked = st%s
                    call set_rest(st, st%t)
                case (R_CAP)
                    call finish_overturn(st, run)
                    return
                case (R_LIMIT)
                    call finish(st, run, ROCK_RUN_TIME_LIMIT)
                    return
                end select
            end if
        end do
        call finish(st, run, ROCK_RUN_TIME_LIMIT)
    end subroutine run_segment

    !> At rest on a monotone piece: find the uplift (doc/rocking.md section 1, Eq. 2.3), a root of
    !> a_g -+ threshold (Brent), or move to t_stop.
    subroutine rest_scan(st, run, t_stop)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        real(dp) :: a_c, a_e, lev, t_u, v_c, v_e, tu, lev_n, t_n
        integer :: dir, dir_n
        logical :: now, now_n
        associate(gr => st%sys%gr, sim => st%sys%sim)
        if (gr%src == GR_ZERO) then
            call fill_rest(st, t_stop)
            st%t = t_stop
            return
        end if
        a_c = ground_accel(gr, st%t)
        a_e = gr%ab
        t_u = st%t
        if (gr%vsrc == V_RECORD) then
            ! doc/rocking.md (R.10): side +1 when a_g - tan_u a_v > g tan_u, side -1 when
            ! a_g + tan_u a_v < -g tan_u: two lines in t on a record step (never both at
            ! once, as a_v >= -g); the earlier root when both are crossed later
            tu = sim%tan_u
            v_c = ground_vert(gr, st%t)
            v_e = gr%vb
            call onset_on_piece(a_c - tu * v_c, a_e - tu * v_e, sim%thr_pos, huge(1.0_dp), &
                                st%blocked, dir, lev, now)
            call onset_on_piece(a_c + tu * v_c, a_e + tu * v_e, huge(1.0_dp), sim%thr_neg, &
                                st%blocked, dir_n, lev_n, now_n)
            if (dir /= 0 .and. now) then
                dir_n = 0
            else if (dir_n /= 0 .and. now_n) then
                dir = dir_n
            else
                if (dir /= 0) then
                    call uplift_root(st, tu, lev, a_c - tu * v_c, a_e - tu * v_e, t_stop, t_u)
                    if (st%stat /= SEISPULSE_SUCCESS) return
                end if
                if (dir_n /= 0) then
                    call uplift_root(st, -tu, lev_n, a_c + tu * v_c, a_e + tu * v_e, t_stop, t_n)
                    if (st%stat /= SEISPULSE_SUCCESS) return
                    if (dir == 0 .or. t_n < t_u) then
                        dir = dir_n
                        t_u = t_n
                    end if
                end if
            end if
        else
            call onset_on_piece(a_c, a_e, sim%thr_pos, sim%thr_neg, st%blocked, dir, lev, now)
            if (dir /= 0 .and. .not. now) then
                call uplift_root(st, 0.0_dp, lev, a_c, a_e, t_stop, t_u)
                if (st%stat /= SEISPULSE_SUCCESS) return
            end if
        end if
        if (dir == 0) then
            call fill_rest(st, t_stop)
            st%t = t_stop
            return
        end if
        call start_flight(st, run, t_u, dir)
        end associate
    end subroutine rest_scan

    !> Uplift on a monotone piece: the root in [st%t, t_stop] of a_g - tu a_v - lev (Brent;
    !> tu = 0 without a vertical record, else +-tan_u), fa and fb the values of a_g - tu a_v
    !> at the ends.
    subroutine uplift_root(st, tu, lev, fa, fb, t_stop, t_u)
        type(rocking_state_t), intent(inout) :: st
        real(dp), intent(in) :: tu, lev, fa, fb, t_stop
        real(dp), intent(out) :: t_u
        character(len=120) :: rmsg
        st%sys%gr%level = lev
        st%sys%gr%vmix = -tu
        rmsg = ''
        call find_root(st%sys%gr, st%t, t_stop, t_u, st%stat, rmsg, fa_known=fa - lev, &
                       fb_known=fb - lev)
        if (st%stat /= SEISPULSE_SUCCESS) then
            st%msg = 'rocking: uplift location failed after t = '//real_str(st%t)//': ' &
                     //trim(rmsg)//' (a bug)'
            st%stat = SEISPULSE_INTERNAL
            return
        end if
        t_u = min(max(t_u, st%t), t_stop)
    end subroutine uplift_root

    !> The block at rest uplifts at t_u on side dir (or the run reaches its limit first).
    subroutine start_flight(st, run, t_u, dir)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_u
        integer, intent(in) :: dir
        if (t_u > st%t_lim) then
            call fill_rest(st, st%t_lim)
            st%t = st%t_lim
            call finish(st, run, ROCK_RUN_TIME_LIMIT)
            return
        end if
        call fill_rest(st, t_u)
        st%t = t_u
        st%mode = 1
        st%s = dir
        st%sys%sa = st%sys%sim%alpha * real(st%s, dp)
        st%y = 0.0_dp
        st%from_zero = .true.
        if (.not. st%ever_up) then
            st%ever_up = .true.
            run%t_uplift = t_u
        end if
    end subroutine start_flight

    !> Integrate the flight from (t, y) on side s up to t_stop, handling impacts
    !> (restitution, rest), the outward crossings of alpha and |theta| = pi/2.
    subroutine advance(st, run, t_stop, stop_on_impact, why)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        logical, intent(in) :: stop_on_impact
        integer, intent(out) :: why
        real(dp) :: hh, t_new, y_new(2), f_new(2), err, fac, u0, u1, w0, w1
        real(dp) :: x_turn, u_turn, x_ev, x_end, u_end, xr, yv(2), acc0, tau, t_r, amp
        real(dp) :: fa, rs_
        integer :: ev, kk
        logical :: turn, max_turn, need, rejected, clamped

        associate(sim => st%sys%sim, t => st%t, y => st%y, f => st%f, h => st%h, &
                  ig => st%ig, ng => st%ng, ode => st%ode)
        why = R_REACHED
        rs_ = real(st%s, dp)
        call st%sys%rhs(t, y, f)
        rejected = .false.
        do kk = 1, sim%max_steps
            if (.not. t < t_stop) return
            if (st%steps >= sim%max_steps) then
                why = R_LIMIT
                return
            end if
            st%steps = st%steps + 1
            ! at most half the block's time scale: one turning point per step at most
            h = min(h, 0.5_dp / sim%p)
            clamped = .not. h < t_stop - t
            if (clamped) then
                t_new = t_stop
            else
                t_new = t + h
            end if
            hh = t_new - t
            if (hh < min_step(sim, t)) then
                if (st%from_zero) then
                    ! no flight of any length leaves the base: not an uplift
                    why = R_TOUCH
                    return
                else if (clamped) then
                    ! a sliver of a piece below the time resolution: step over it
                    t = t_new
                    cycle
                end if
                why = R_LIMIT
                return
            end if
            call ode%step(st%sys, t, y, f, hh, t_new, y_new, f_new, err)
            if (.not. err <= 1.0_dp) then
                rejected = .true.
                h = hh * ode_dop853_factor(err)
                cycle
            end if
            u1 = rs_ * y_new(1)
            if (st%from_zero .and. .not. u1 > 0.0_dp) then
                ! the first step of a flight must leave the base: shorter
                h = 0.25_dp * hh
                cycle
            end if
            fac = ode_dop853_factor(err)
            if (rejected) fac = min(fac, 1.0_dp)
            rejected = .false.
            st%from_zero = .false.
            u0 = rs_ * y(1)
            w0 = rs_ * y(2)
            w1 = rs_ * y_new(2)
            ! turning point: a maximum of s theta (w from >= 0 to < 0) or a minimum
            max_turn = w0 >= 0.0_dp .and. w1 < 0.0_dp
            turn = max_turn .or. (w0 < 0.0_dp .and. w1 > 0.0_dp)
            need = u1 <= 0.0_dp .or. u1 >= half_pi .or. (turn .and. .not. max_turn)
            if (sim%track) need = need .or. turn .or. (u0 < sim%alpha .and. u1 >= sim%alpha)
            if (ig <= ng) need = need .or. st%t_grid(ig) <= t_new
            ev = 0
            x_ev = 1.0_dp
            x_turn = 0.0_dp
            u_turn = u0
            if (need) then
                call ode%dense_setup(st%sys, t, y, f, hh, y_new, f_new)
                if (turn) then
                    ! w0 = 0 only at an uplift, where the block starts outward
                    fa = w0
                    if (.not. abs(w0) > 0.0_dp) fa = tiny(fa)
                    call locate(st, 2, rs_, 0.0_dp, 0.0_dp, 1.0_dp, fa, w1, x_turn)
                    if (st%stat /= SEISPULSE_SUCCESS) return
                    call ode%value(x_turn, yv)
                    u_turn = rs_ * yv(1)
                end if
                if (max_turn) then
                    if (u_turn >= half_pi) then
                        ev = R_CAP
                        call locate(st, 1, rs_, half_pi, 0.0_dp, x_turn, u0 - half_pi, &
                                    u_turn - half_pi, x_ev)
                    else if (u1 <= 0.0_dp) then
                        ev = R_IMPACT
                        call locate(st, 1, rs_, 0.0_dp, x_turn, 1.0_dp, u_turn, u1, x_ev)
                    end if
                else if (turn) then
                    if (u_turn <= 0.0_dp) then
                        ev = R_IMPACT
                        call locate(st, 1, rs_, 0.0_dp, 0.0_dp, x_turn, u0, u_turn, x_ev)
                    else if (u1 >= half_pi) then
                        ev = R_CAP
                        call locate(st, 1, rs_, half_pi, x_turn, 1.0_dp, u_turn - half_pi, &
                                    u1 - half_pi, x_ev)
                    end if
                else if (u1 <= 0.0_dp) then
                    ev = R_IMPACT
                    call locate(st, 1, rs_, 0.0_dp, 0.0_dp, 1.0_dp, u0, u1, x_ev)
                else if (u1 >= half_pi) then
                    ev = R_CAP
                    call locate(st, 1, rs_, half_pi, 0.0_dp, 1.0_dp, u0 - half_pi, &
                                u1 - half_pi, x_ev)
                end if
                if (st%stat /= SEISPULSE_SUCCESS) return
            end if
            x_end = x_ev
            if (ev == R_IMPACT) then
                u_end = 0.0_dp
            else if (ev == R_CAP) then
                u_end = half_pi
            else
                u_end = u1
            end if
            if (sim%track) then
                ! extremes of theta and the last outward crossing of |theta| = alpha
                ! (not when the step ends in an impact: the block is then back at 0)
                if (turn .and. x_turn <= x_end) call extremes(run, rs_ * u_turn, &
                                                              t + x_turn * hh)
                call extremes(run, rs_ * u_end, t + x_end * hh)
                if (ev /= R_IMPACT) then
                    xr = -1.0_dp
                    if (max_turn .and. x_turn <= x_end) then
                        if (u0 < sim%alpha .and. u_turn >= sim%alpha) &
                            call locate(st, 1, rs_, sim%alpha, 0.0_dp, x_turn, &
                                        u0 - sim%alpha, u_turn - sim%alpha, xr)
                    else if (turn .and. x_turn <= x_end) then
                        if (u_turn < sim%alpha .and. u_end >= sim%alpha) &
                            call locate(st, 1, rs_, sim%alpha, x_turn, x_end, &
                                        u_turn - sim%alpha, u_end - sim%alpha, xr)
                    else if (u0 < sim%alpha .and. u_end >= sim%alpha) then
                        call locate(st, 1, rs_, sim%alpha, 0.0_dp, x_end, u0 - sim%alpha, &
                                    u_end - sim%alpha, xr)
                    end if
                    if (st%stat /= SEISPULSE_SUCCESS) return
                    if (xr >= 0.0_dp) st%t_cross = t + xr * hh
                end if
            end if
            ! grid points inside the step
            do while (ig <= ng)
                if (ev == 0) then
                    if (st%t_grid(ig) > t_new) exit
                else
                    if (st%t_grid(ig) > t + x_ev * hh) exit
                end if
                call ode%value(min(max((st%t_grid(ig) - t) / hh, 0.0_dp), 1.0_dp), yv)
                st%th_grid(ig) = yv(1)
                st%om_grid(ig) = yv(2)
                ig = ig + 1
            end do
            if (clamped) then
                h = max(h, hh * fac)
            else
                h = hh * fac
            end if
            if (ev == 0) then
                t = t_new
                y = y_new
                f = f_new
                cycle
            end if
            ! an event ends the step
            call ode%value(x_ev, yv)
            if (x_ev < 1.0_dp) then
                t = t + x_ev * hh
            else
                t = t_new
            end if
            if (ev == R_CAP) then
                y = [rs_ * half_pi, yv(2)]
                why = R_CAP
                return
            end if
            ! impact (doc/rocking.md section 6): onto the other corner, theta' times e
            st%n_imp = st%n_imp + 1
            if (sim%track) call push_impact(st, t)
            st%s = -st%s
            rs_ = real(st%s, dp)
            st%sys%sa = sim%alpha * rs_
            y = [0.0_dp, sim%e * yv(2)]
            call st%sys%rhs(t, y, f)
            acc0 = f(2)
            if (.not. rs_ * acc0 > 0.0_dp) then
                ! pushed back onto the base: the next flight rises theta'^2/(2|theta''|)
                if (abs(acc0) > 0.0_dp) then
                    amp = 0.5_dp * y(2)**2 / abs(acc0)
                else if (abs(y(2)) > 0.0_dp) then
                    amp = huge(amp)
                else
                    amp = 0.0_dp
                end if
                if (amp <= sim%rest_amp) then
                    ! rest (ends a Zeno sequence): flights tau, e tau, ... sum tau/(1-e)
                    t_r = t
                    if (abs(acc0) > 0.0_dp .and. sim%e < 1.0_dp) then
                        tau = 2.0_dp * abs(y(2)) / abs(acc0)
                        t_r = t + tau / (1.0_dp - sim%e)
                    end if
                    call set_rest(st, min(t_r, t_stop))
                    why = R_REST
                    return
                end if
                ! a flight of 2|theta'|/|theta''|: start with a quarter of it
                h = min(h, 0.5_dp * abs(y(2)) / abs(acc0))
            end if
            st%from_zero = .true.
            if (stop_on_impact) then
                why = R_IMPACT
                return
            end if
        end do
        why = R_LIMIT
        end associate
    end subroutine advance

    !> Root of sgn * component - level of the dense output on [xa, xb], given the
    !> values fa, fb at the ends (of opposite signs, or one of them 0).
    subroutine locate(st, comp, sgn, level, xa, xb, fa, fb, x)
        type(rocking_state_t), intent(inout) :: st
        integer, intent(in) :: comp
        real(dp), intent(in) :: sgn, level, xa, xb, fa, fb
        real(dp), intent(out) :: x
        character(len=120) :: rmsg
        rmsg = ''
        call st%ode%locate(comp, sgn, level, xa, xb, fa, fb, x, st%stat, rmsg)
        if (st%stat /= SEISPULSE_SUCCESS) then
            st%msg = 'rocking: event location failed after t = '//real_str(st%t)//': ' &
                     //trim(rmsg)//' (a bug)'
            st%stat = SEISPULSE_INTERNAL
            st%done = .true.
        end if
    end subroutine locate

    !> The block is back at rest at tt (grid points up to tt: 0).
    subroutine set_rest(st, tt)
        type(rocking_state_t), intent(inout) :: st
        real(dp), intent(in) :: tt
        call fill_rest(st, tt)
        st%t = max(st%t, tt)
        st%t_rest = st%t
        st%mode = 0
        st%s = 0
        st%sys%sa = 0.0_dp
        st%y = 0.0_dp
        st%from_zero = .false.
    end subroutine set_rest

    !> A new extreme theta at time t_th (s): the first time each extreme is reached.
    pure subroutine extremes(run, th, t_th)
        type(rocking_run_t), intent(inout) :: run
        real(dp), intent(in) :: th, t_th
        if (th > run%theta_max) then
            run%theta_max = th
            run%t_theta_max = t_th
        end if
        if (th < run%theta_min) then
            run%theta_min = th
            run%t_theta_min = t_th
        end if
    end subroutine extremes

    subroutine push_impact(st, tt)
        type(rocking_state_t), intent(inout) :: st
        real(dp), intent(in) :: tt
        real(dp), allocatable :: tmp(:)
        if (st%n_imp > size(st%imp)) then
            allocate(tmp(2 * size(st%imp)))
            tmp(1:size(st%imp)) = st%imp
            call move_alloc(tmp, st%imp)
        end if
        st%imp(st%n_imp) = tt
    end subroutine push_impact

    !> Grid points up to tt while at rest.
    subroutine fill_rest(st, tt)
        type(rocking_state_t), intent(inout) :: st
        real(dp), intent(in) :: tt
        do while (st%ig <= st%ng)
            if (st%t_grid(st%ig) > tt) exit
            st%th_grid(st%ig) = 0.0_dp
            st%om_grid(st%ig) = 0.0_dp
            st%ig = st%ig + 1
        end do
    end subroutine fill_rest

    !> Overturned (|theta| = pi/2, or certain once the excitation is over).
    subroutine finish_overturn(st, run)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        if (st%n_imp == 0) then
            call finish(st, run, ROCK_RUN_OVERTURN_NO_IMPACT)
        else if (st%n_imp == 1) then
            call finish(st, run, ROCK_RUN_OVERTURN_ONE_IMPACT)
        else
            call finish(st, run, ROCK_RUN_OVERTURN_MANY)
        end if
    end subroutine finish_overturn

    subroutine finish_rest(st, run)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        if (st%ever_up) then
            call finish(st, run, ROCK_RUN_REST)
        else
            call finish(st, run, ROCK_RUN_NO_UPLIFT)
        end if
    end subroutine finish_rest

    !> Fill the run and the rest of the grid.
    subroutine finish(st, run, outcome)
        type(rocking_state_t), intent(inout) :: st
        type(rocking_run_t), intent(inout) :: run
        integer, intent(in) :: outcome
        real(dp) :: th_after, om_after
        st%done = .true.
        run%outcome = outcome
        run%n_impacts = st%n_imp
        run%n_steps = st%steps
        select case (outcome)
        case (ROCK_RUN_NO_UPLIFT)
            run%t_end = 0.0_dp
            th_after = 0.0_dp
            om_after = 0.0_dp
        case (ROCK_RUN_REST)
            run%t_end = st%t_rest
            th_after = 0.0_dp
            om_after = 0.0_dp
        case (ROCK_RUN_TIME_LIMIT)
            run%t_end = st%t
            th_after = ieee_value(th_after, ieee_quiet_nan)
            om_after = th_after
        case default
            ! overturned: on its side
            run%t_end = st%t
            run%t_overturn = st%t_cross
            if (st%s < 0) then
                th_after = -half_pi
            else
                th_after = half_pi
            end if
            om_after = 0.0_dp
        end select
        do while (st%ig <= st%ng)
            st%th_grid(st%ig) = th_after
            st%om_grid(st%ig) = om_after
            st%ig = st%ig + 1
        end do
        if (st%sys%sim%track) then
            if (allocated(run%t_impacts)) deallocate(run%t_impacts)
            allocate(run%t_impacts(st%n_imp))
            run%t_impacts(:) = st%imp(1:st%n_imp)
        end if
    end subroutine finish

    !> Outcome known once the excitation is over (module notes; doc/rocking.md (R.7), (R.8)): the
    !> energy above the barrier, D, is kept by every flight and lowered by every impact.
    pure function decide(sim, y, s) result(dec)
        type(sim_t), intent(in) :: sim
        real(dp), intent(in) :: y(2)
        integer, intent(in) :: s
        integer :: dec
        real(dp) :: ath, d, outward
        ath = abs(y(1))
        outward = real(s, dp) * y(2)
        if (sim%lin) then
            d = 0.5_dp * y(2)**2 - 0.5_dp * sim%p2 * (sim%alpha - ath)**2
        else
            d = 0.5_dp * y(2)**2 - 2.0_dp * sim%p2 * sin(0.5_dp * (sim%alpha - ath))**2
        end if
        dec = DEC_OPEN
        if (ath >= sim%alpha) then
            ! beyond the barrier gravity pushes outward
            if (outward >= 0.0_dp .or. d <= 0.0_dp) dec = DEC_OVERTURN
        else if (d <= 0.0_dp) then
            dec = DEC_SAFE
        else if (outward > 0.0_dp) then
            dec = DEC_OVERTURN
        end if
    end function decide

    !> Smallest meaningful step at time t (a few ulps of t, or of 1e-3/p near t = 0).
    pure function min_step(sim, t) result(h)
        type(sim_t), intent(in) :: sim
        real(dp), intent(in) :: t
        real(dp) :: h
        h = 16.0_dp * epsilon(t) * max(abs(t), 1.0e-3_dp / sim%p)
    end function min_step

    ! ------------------------------------------------------------------------------
    ! Equation of motion
    ! ------------------------------------------------------------------------------

    !> (theta', theta'') on side s (sa = alpha s): Eqs. 2.5/2.6 or 2.7; the right-hand
    !> side of the flight for seispulse_ode (a static call from this module).
    subroutine flight_ode_rhs(self, t, y, dydt)
        class(flight_ode_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        real(dp) :: a, phi, f(2)
        if (self%gr%vsrc /= V_NONE) then
            ! with a vertical component: apart, with scalar arguments, so that the lines
            ! below compile (and run) as they do without it
            f(1) = y(2)
            call flight_vert_rhs(self%sim, self%gr, self%sa, t, y(1), f(2))
            dydt(1:2) = f
            return
        end if
        a = ground_accel(self%gr, t) * self%sim%inv_g
        f(1) = y(2)
        if (self%sim%lin) then
            f(2) = self%sim%p2 * (y(1) + a - self%sa)
        else
            phi = self%sa - y(1)
            f(2) = -self%sim%p2 * (sin(phi) - a * cos(phi))
        end if
        dydt(1:2) = f   ! one store: the integrator reads the pair at once
    end subroutine flight_ode_rhs

    !> theta'' (rad/s^2) with gravity g + a_v (doc/rocking.md (R.9)): flight_ode_rhs with a
    !> vertical component (gv = 1 gives its horizontal-only lines bit for bit).
    subroutine flight_vert_rhs(sim, gr, sa, t, theta, acc)
        type(sim_t), intent(in) :: sim             !! settings of the run
        type(ground_t), intent(in) :: gr           !! ground on the current piece
        real(dp), intent(in) :: sa                 !! alpha s
        real(dp), intent(in) :: t                  !! time (s)
        real(dp), intent(in) :: theta              !! rotation (rad)
        real(dp), intent(out) :: acc               !! theta''
        real(dp) :: a, gv, phi
        a = ground_accel(gr, t) * sim%inv_g
        if (gr%vsrc == V_SCALED) then
            gv = 1.0_dp + gr%kv * a
        else
            gv = 1.0_dp + ground_vert(gr, t) * sim%inv_g
        end if
        if (sim%lin) then
            acc = sim%p2 * (gv * theta + a - gv * sa)
        else
            phi = sa - theta
            acc = -sim%p2 * (gv * sin(phi) - a * cos(phi))
        end if
    end subroutine flight_vert_rhs

    ! ------------------------------------------------------------------------------
    ! Ground acceleration
    ! ------------------------------------------------------------------------------

    !> a_g at t on the current piece; at and after its end the limit from inside.
    pure function ground_accel(gr, t) result(a)
        type(ground_t), intent(in) :: gr
        real(dp), intent(in) :: t
        real(dp) :: a
        select case (gr%src)
        case (GR_PULSE)
            if (t >= gr%tb) then
                a = gr%ab
            else
                a = pulse_accel(gr%p, t, gr%cexp)
            end if
        case (GR_RECORD)
            a = step_line(gr, t, gr%a0, gr%slope, gr%ab)
        case default
            a = 0.0_dp
        end select
    end function ground_accel

    !> On a record step: the line a0 + slope (t - ta), and from its end on the limit from
    !> inside, ab (the horizontal or the vertical record).
    pure function step_line(gr, t, a0, slope, ab) result(a)
        type(ground_t), intent(in) :: gr
        real(dp), intent(in) :: t, a0, slope, ab
        real(dp) :: a
        if (t >= gr%tb) then
            a = ab
        else
            a = a0 + slope * (t - gr%ta)
        end if
    end function step_line

    !> Vertical ground acceleration a_v (m/s^2, positive up) at t on the current piece
    !> (doc/rocking.md section 7); 0 once the excitation is over.
    pure function ground_vert(gr, t) result(a)
        type(ground_t), intent(in) :: gr
        real(dp), intent(in) :: t
        real(dp) :: a
        a = 0.0_dp
        if (gr%src == GR_ZERO) return
        select case (gr%vsrc)
        case (V_SCALED)
            a = gr%kv * ground_accel(gr, t)
        case (V_RECORD)
            a = step_line(gr, t, gr%v0, gr%vslope, gr%vb)
        end select
    end function ground_vert

    !> The vertical record's step (record_step of seispulse_pieces, m/s^2) as the line
    !> v0 + vslope (t - ta), vb at the end, like the horizontal of `load_piece`.
    pure subroutine load_vert(gr, step)
        type(ground_t), intent(inout) :: gr
        type(piece_t), intent(in) :: step
        gr%v0 = step%aa
        gr%vb = step%ab
        gr%vslope = step%slope
    end subroutine load_vert

    !> Make a piece of seispulse_pieces the current piece of gr: from its end on, a_g is
    !> the limit from inside, ab; a record step is the line aa + slope (t - ta).
    pure subroutine load_piece(gr, piece)
        type(ground_t), intent(inout) :: gr
        type(piece_t), intent(in) :: piece
        gr%ta = piece%ta
        gr%tb = piece%tb
        gr%ab = piece%ab
        if (gr%src == GR_RECORD) then
            gr%a0 = piece%aa
            gr%slope = piece%slope
        end if
    end subroutine load_piece

    function ground_eval(self, x) result(y)
        class(ground_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        if (self%vsrc == V_RECORD) then
            ! uplift function s a_g - (g + a_v) tan(alpha) up to a constant: doc/rocking.md (R.10)
            y = ground_accel(self, x) + self%vmix * ground_vert(self, x) - self%level
        else
            y = ground_accel(self, x) - self%level
        end if
    end function ground_eval

end module seispulse_rocking_sim
