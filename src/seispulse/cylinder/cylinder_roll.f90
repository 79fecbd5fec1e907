!> Rocking with rolling of a rigid circular cylinder on its base rim, without slip, on a
!> rigid horizontally shaken base ([KM90]'s problem; doc/rolling.md).
!>
!> Model (doc/rolling.md section 2). Z-X-Z Euler angles: heading psi, tilt theta >= 0 and
!> spin phi_s; body axis e3 = (sin theta sin psi, -sin theta cos psi, cos theta), nodal line
!> n = (cos psi, sin psi, 0) (the rim tangent at the contact point P), d = Z x n (the
!> horizontal unit vector pointing away from the side the body leans to), m = e3 x n, and
!> rho = r m + h e3 from P to the centre of mass G (L.1). The body leans towards -d.
!> Angular velocities omega = theta' n + psi' Z + phi_s' e3 and Omega = theta' n + psi' Z
!> (of the contact frame, L.2); no slip: v_G = omega x rho (L.3), relative to the ground.
!> Moments about the contact point (L.4):
!>     I_G omega' + omega x I_G omega + m rho x (omega' x rho) + m rho x (omega x (Omega x rho))
!>         = rho x (-m g Z - m a_g),
!> with I_G = A (1 - e3 e3) + C e3 e3 (A = body%j_g, C = body%j_axis) and
!> omega' = theta'' n + psi'' Z + phi_s'' e3 + theta' psi' d + phi_s' (Omega x e3) (L.5).
!> The unknowns are taken as (theta'', psi'' + cos(theta) phi_s'', sin(theta) phi_s'') on the
!> orthonormal triad (n, Z, -d), so the 3x3 system (L.6) is the inertia about P on that
!> triad, never singular; it is solved by LAPACK (seispulse_lapack's
!> solve_linear_inplace, no allocation). The Euler-angle singularity is then a division
!> by sin(theta) alone, replaced below the floor theta_floor (see Rules) by the continuous
!> ramp sin(theta)/sin^2(theta_floor), where no pass is followed anyway.
!> The contact force is R = m (a_G + g Z + a_g) (L.8), N = R.Z; the friction demand is
!> |R_t|/N. Energy in the ground frame E = m v_G^2/2 + omega.I_G omega/2 + m g z_G (L.9),
!> conserved between impacts in free motion.
!>
!> Rules (doc/rolling.md section 4).
!> - Uplift from rest as in the planar model: |a_g| > g tan(theta_c), the rocking plane
!>   along a_g at that instant (the body leans away from a_g: d = a_g/|a_g|).
!> - Impact when theta reaches 0 with theta' < 0 (the equations are continued past
!>   theta = 0 on the same rim point, so the root is located on the dense output of the
!>   step): the contact jumps to the opposite rim point, psi -> psi + pi and
!>   phi_s -> phi_s - pi (the same pose: psi + phi_s continuous), theta' -> e |theta'|,
!>   psi', phi_s' (the vertical angular velocity) kept.
!> - Floor: a pass with spin turns around above theta = 0 (physically: no impact, the
!>   contact runs round the rim fast, psi' ~ 1/theta^2). A pass whose minimum lies below
!>   theta_floor = 1e-5 theta_c (the opposite rim within 2 r theta_floor of the ground)
!>   counts as an impact at the downward crossing of theta_floor (theta kept, the contact
!>   mirrored to the opposite rim point; a motion in a fixed plane, psi' = phi_s' = 0,
!>   goes on to its impact at theta = 0); a step that cannot be resolved above the time
!>   resolution with theta < 1e-3 theta_c also counts as one (a touch; the flight goes
!>   on with a fresh step). A first step from theta = 0 that cannot rise is no flight:
!>   after an uplift the threshold was only touched, after an impact rest. Every loop is
!>   bounded by the step budget (2e6 attempted steps, 40 more per record sample).
!> - Rest: after an impact, when the next flight would rise less than 1e-10 theta_c (the
!>   planar model's rule); after a floor pass, also when the rocking left, J_n theta'^2/2
!>   (about the rim tangent; the potential from the floor), is below m g r 1e-10 theta_c
!>   (the same measure). The body
!>   then sits on its base (all rates set to 0: no base torque is modelled), from the
!>   impact time plus the Zeno estimate tau/(1 - e) (after a floor pass: at once).
!> - Overturned when theta reaches pi/2. After the excitation, E < m g R with
!>   theta < theta_c proves that the body never overturns (doc/rolling.md section 4):
!>   with e = 1 and t_max = +inf the run then ends at the last output time.
!>
!> Method: DOP853 of seispulse_ode on the state (theta, psi, phi_s, theta', psi', phi_s',
!> x_G, y_G), steps ending on the pieces of the excitation (seispulse_pieces), at most
!> 0.5/max(p, |psi'|, C |omega_Z|/A) long (one turning point of theta per step), events on
!> the dense output; a step that is not finite or whose theta leaves [-pi, pi] is rejected.
module seispulse_cylinder_roll
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan, ieee_value, &
                                             ieee_quiet_nan
    use seispulse_kinds, only: dp, ik
    use seispulse_checks, only: finite_positive, in_closed, in_open, check_ascending_times
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_special, only: pi
    use seispulse_lapack, only: solve_linear_inplace
    use seispulse_ode, only: ode_system, ode_dop853_t, ode_dop853_factor
    use seispulse_pulses, only: pulse_t, pulse_validate, pulse_accel, exp_consts_t, exp_consts, &
                                PULSE_EXPONENTIAL
    use seispulse_pieces, only: piece_t, piece_iter_t, pulse_pieces_check, record_step_check, &
                                record_pieces_check, record_in_si, pulse_pieces_init, record_pieces_init, &
                                next_piece, onset_on_piece, record_step, piece_step
    use seispulse_cylinder, only: rocking_body_t
    implicit none
    private

    public :: cylinder_roll, roll_run_t, roll_output_name, roll_outcome_name
    public :: ROLL_NOUT, ROLL_OUT_THETA, ROLL_OUT_PSI, ROLL_OUT_SPIN, ROLL_OUT_THETA_RATE, &
              ROLL_OUT_PSI_RATE, ROLL_OUT_SPIN_RATE, ROLL_OUT_XP, ROLL_OUT_YP, ROLL_OUT_XG, &
              ROLL_OUT_YG, ROLL_OUT_NORMAL, ROLL_OUT_FRICTION, ROLL_OUT_ENERGY
    public :: ROLL_RUN_REST, ROLL_RUN_NO_UPLIFT, ROLL_RUN_OVERTURN, ROLL_RUN_TIME_LIMIT

    integer, parameter :: ROLL_OUT_THETA = 1       !! tilt theta (rad), >= 0
    integer, parameter :: ROLL_OUT_PSI = 2         !! heading psi (rad), continuous but for
                                                   !! the jumps of pi at impacts
    integer, parameter :: ROLL_OUT_SPIN = 3        !! spin phi_s (rad), jumps by -pi where
                                                   !! psi jumps by pi (psi + phi_s continuous)
    integer, parameter :: ROLL_OUT_THETA_RATE = 4  !! theta' (rad/s)
    integer, parameter :: ROLL_OUT_PSI_RATE = 5    !! psi' (rad/s)
    integer, parameter :: ROLL_OUT_SPIN_RATE = 6   !! phi_s' (rad/s)
    integer, parameter :: ROLL_OUT_XP = 7          !! contact point x on the ground (m)
    integer, parameter :: ROLL_OUT_YP = 8          !! contact point y on the ground (m)
    integer, parameter :: ROLL_OUT_XG = 9          !! centre of mass x (m), ground frame
    integer, parameter :: ROLL_OUT_YG = 10         !! centre of mass y (m), ground frame
    integer, parameter :: ROLL_OUT_NORMAL = 11     !! normal contact force N (N)
    integer, parameter :: ROLL_OUT_FRICTION = 12   !! friction demand |F_t|/N (-)
    integer, parameter :: ROLL_OUT_ENERGY = 13     !! kinetic + potential energy (J)
    integer, parameter :: ROLL_NOUT = 13           !! number of output columns

    integer, parameter :: ROLL_RUN_REST = 0        !! rocked, then came back to rest
    integer, parameter :: ROLL_RUN_NO_UPLIFT = 1   !! never left the ground
    integer, parameter :: ROLL_RUN_OVERTURN = 2    !! theta reached pi/2
    integer, parameter :: ROLL_RUN_TIME_LIMIT = 3  !! t_max (or the step budget) reached first

    !> Summary of a run.
    type :: roll_run_t
        integer :: outcome = ROLL_RUN_NO_UPLIFT  !! one of the ROLL_RUN_* codes
        real(dp) :: t_uplift = 0.0_dp            !! first uplift (s); 0 for an initial tilt,
                                                 !! NaN if none
        integer :: n_impacts = 0                 !! impacts (theta = 0, and floor passes)
        integer :: n_floor = 0                   !! of which counted by the floor rule
        real(dp), allocatable :: t_impacts(:)    !! impact times (s)
        real(dp) :: theta_max = 0.0_dp           !! largest theta (rad)
        real(dp) :: friction_max = 0.0_dp        !! largest |F_t|/N while N > 0 (-), at the
                                                 !! step ends and output times
        real(dp) :: t_lift_off = 0.0_dp          !! first step end or output time with
                                                 !! N <= 0 (s), NaN if never
        real(dp) :: energy_drift = 0.0_dp        !! largest |E - E_0|/(E_0 - m g h) over the
                                                 !! flights in free motion (E_0 at each
                                                 !! start; E_0 - m g h: above rest)
        real(dp) :: t_end = 0.0_dp               !! rest, overturning or limit time (s)
        integer :: n_steps = 0                   !! integration steps tried
    end type roll_run_t

    real(dp), parameter :: half_pi = 0.5_dp * pi
    real(dp), parameter :: rtol_default = 1.0e-10_dp, rtol_min = 1.0e-14_dp, &
                           rtol_max = 1.0e-3_dp
    !> A flight rising less than rest_tol theta_c is rest (as the planar model).
    real(dp), parameter :: rest_tol = 1.0e-10_dp
    !> Floor of a pass, and the tilt below which an unresolvable step is a touch (x theta_c).
    real(dp), parameter :: floor_tol = 1.0e-5_dp, touch_tol = 1.0e-3_dp
    integer, parameter :: max_steps_default = 2000000, steps_per_sample = 40
    integer, parameter :: RG_ZERO = 0, RG_PULSE = 1, RG_RECORD = 2
    integer, parameter :: WHY_REACHED = 0, WHY_REST = 2, WHY_CAP = 3, WHY_LIMIT = 4, &
                          WHY_TOUCH = 5
    integer, parameter :: EV_NONE = 0, EV_IMPACT = 1, EV_FLOOR = 2, EV_CAP = 3
    integer, parameter :: NY = 8

    !> Ground acceleration (m/s^2) on the current piece; as a scalar function, the pulse's
    !> a(t) - level (uplift roots).
    type, extends(scalar_function) :: roll_ground_t
        integer :: src = RG_ZERO
        type(pulse_t) :: p                  !! the pulse (RG_PULSE), along (ux, uy)
        type(exp_consts_t) :: cexp
        real(dp) :: ux = 1.0_dp, uy = 0.0_dp
        real(dp) :: ta = 0.0_dp, tb = 0.0_dp
        real(dp) :: ab = 0.0_dp             !! pulse: a(tb-)
        real(dp) :: ax0 = 0.0_dp, ay0 = 0.0_dp, sx = 0.0_dp, sy = 0.0_dp  !! record step
        real(dp) :: abx = 0.0_dp, aby = 0.0_dp  !! record: a(tb-)
        real(dp) :: level = 0.0_dp
    contains
        procedure :: eval => ground_eval
    end type roll_ground_t

    !> The rolling body as a system of seispulse_ode (state: see the module notes).
    type, extends(ode_system) :: roll_ode_t
        real(dp) :: r = 1.0_dp, h = 1.0_dp, m = 1.0_dp, g = 9.80665_dp
        real(dp) :: ia = 1.0_dp             !! A = J_G, transverse (kg m^2)
        real(dp) :: ic = 1.0_dp             !! C = J_axis (kg m^2)
        real(dp) :: s_reg = 0.0_dp          !! regularisation of 1/sin(theta) (L.7)
        type(roll_ground_t) :: gr
        real(dp) :: mat(3, 3) = 0.0_dp      !! solve workspace
        real(dp) :: vec(3) = 0.0_dp
        integer(ik) :: ipiv(3) = 0
        integer :: stat = SEISPULSE_SUCCESS !! a failed solve (not expected)
    contains
        procedure :: rhs => roll_rhs
    end type roll_ode_t

    !> State of a run.
    type :: roll_state_t
        type(roll_ode_t) :: sys
        type(ode_dop853_t) :: ode
        real(dp) :: t = 0.0_dp, y(NY) = 0.0_dp, f(NY) = 0.0_dp, h = 0.0_dp
        real(dp) :: theta_c = 0.0_dp, big_r = 0.0_dp, p = 1.0_dp, e = 0.0_dp
        real(dp) :: thr = 0.0_dp            !! uplift threshold on |a_g| (m/s^2)
        real(dp) :: t_lim = 0.0_dp
        real(dp) :: e_ref = 0.0_dp          !! energy at the start of a free flight (NaN: none)
        real(dp) :: t_rest = 0.0_dp
        integer :: mode = 0                 !! 0 at rest, 1 rocking
        integer :: blocked = 0              !! uplift ruled out on this piece (pulse: side)
        integer :: dir = 0                  !! side of the last uplift under a pulse (+-1)
        integer :: n_imp = 0, n_floor = 0, steps = 0, max_steps = max_steps_default
        integer :: ig = 1, ng = 0
        logical :: from_zero = .false., ever_up = .false., done = .false.
        logical :: uplifting = .false.      !! from_zero after an uplift from rest
        real(dp), allocatable :: imp(:)
        real(dp), allocatable :: tg(:)
        integer :: stat = SEISPULSE_SUCCESS
        character(len=:), allocatable :: msg
    end type roll_state_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Rocking with rolling of `body` (a cylinder, or any body of revolution with j_g and
    !> j_axis) from an initial state or from rest, under a pulse of seispulse_pulses (SI)
    !> along the fixed horizontal direction `direction` (rad from the x axis), or under a
    !> two-component record accel_x, accel_y (in units of g_rec m/s^2, at t = (i-1) dt,
    !> linear in between, 0 after the last sample), or free (neither).
    !>
    !> hist(:, k) holds the ROLL_OUT_* columns at t_grid(k) (finite, ascending; times <= 0
    !> give the initial state). After overturning: theta = pi/2, the rest frozen, the rates 0
    !> and N, |F_t|/N, E NaN; after a time limit all NaN. The run ends at rest, overturning
    !> or t_max (default: the last output time; +inf: until rest or overturning, or the
    !> step budget). e: restitution (default body%e), in [0, 1]. Initial state: theta0 in
    !> [0, pi/2) (rad) with psi0, spin0 (rad) and the rates (rad/s): theta0 = 0 with all
    !> rates 0 starts at rest; theta0 = 0 needs psi_rate0 = spin_rate0 = 0 (the heading of
    !> an upright body is undefined) and a theta_rate0 < 0 there means the opposite rim.
    !> The centre of mass starts at (0, 0).
    subroutine cylinder_roll(body, t_grid, hist, run, stat, errmsg, theta0, psi0, spin0, &
                             theta_rate0, psi_rate0, spin_rate0, pulse, direction, accel_x, &
                             accel_y, dt, g_rec, e, t_max, rtol)
        type(rocking_body_t), intent(in) :: body              !! the body (m, kg, kg m^2)
        real(dp), intent(in) :: t_grid(:)                     !! output times (s), ascending
        real(dp), intent(out) :: hist(:, :)                   !! ROLL_NOUT x size(t_grid)
        type(roll_run_t), intent(out) :: run                  !! summary
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> initial tilt (rad), [0, pi/2); default 0 (upright)
        real(dp), intent(in), optional :: theta0
        real(dp), intent(in), optional :: psi0                !! initial heading (rad); default 0
        real(dp), intent(in), optional :: spin0               !! initial spin angle (rad); default 0
        real(dp), intent(in), optional :: theta_rate0         !! initial theta' (rad/s); default 0
        real(dp), intent(in), optional :: psi_rate0           !! initial psi' (rad/s); default 0
        !> initial spin rate (rad/s); default 0
        real(dp), intent(in), optional :: spin_rate0
        !> ground acceleration (m/s^2); absent (and no record): free rocking
        type(pulse_t), intent(in), optional :: pulse
        real(dp), intent(in), optional :: direction           !! of the pulse (rad), default 0
        !> record, x component (g_rec); with accel_y and dt, or absent
        real(dp), intent(in), optional :: accel_x(:)
        !> record, y component (g_rec); with accel_x and dt, or absent
        real(dp), intent(in), optional :: accel_y(:)
        !> record sampling step (s), > 0; required with a record
        real(dp), intent(in), optional :: dt
        real(dp), intent(in), optional :: g_rec               !! unit of the record (m/s^2),
                                                              !! default body%g
        real(dp), intent(in), optional :: e                   !! restitution, [0, 1]; default body%e
        !> end of the run (s), > 0 or +inf; default the last output time
        real(dp), intent(in), optional :: t_max
        real(dp), intent(in), optional :: rtol                !! step tolerance; default 1e-10
        type(roll_state_t) :: st
        type(piece_iter_t) :: it
        real(dp) :: y0(NY), beta, gu, rt, ee
        real(dp), allocatable :: ax_si(:), ay_si(:)
        real(dp) :: no_record(0)
        logical :: has_rec

        call empty_run(run)
        hist = ieee_value(1.0_dp, ieee_quiet_nan)
        stat = SEISPULSE_SUCCESS
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(hist, 1) /= ROLL_NOUT .or. size(hist, 2) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'hist: must be ROLL_NOUT x ' &
                           //'size(t_grid)')
            return
        end if
        call check_ascending_times(t_grid, 't_grid', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call initial_state(y0, stat, errmsg, theta0, psi0, spin0, theta_rate0, psi_rate0, &
                           spin_rate0)
        if (stat /= SEISPULSE_SUCCESS) return
        ee = body%e
        if (present(e)) ee = e
        if (.not. in_closed(ee, 0.0_dp, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'e = '//real_str(ee) &
                           //': the coefficient of restitution must be in [0, 1]')
            return
        end if
        rt = rtol_default
        if (present(rtol)) rt = rtol
        if (.not. in_closed(rt, rtol_min, rtol_max)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'rtol = '//real_str(rt) &
                           //': must be in [1e-14, 1e-3]')
            return
        end if
        st%t_lim = huge(1.0_dp)
        if (size(t_grid) > 0) st%t_lim = max(t_grid(size(t_grid)), 0.0_dp)
        if (present(t_max)) then
            if (ieee_is_nan(t_max) .or. .not. t_max > 0.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_max = ' &
                               //real_str(t_max)//': must be a number > 0 (s) or +inf')
                return
            end if
            st%t_lim = min(t_max, huge(1.0_dp))
        end if
        has_rec = present(accel_x) .or. present(accel_y)
        if (present(pulse) .and. has_rec) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pulse, accel_x: give a ' &
                           //'pulse or a record, not both')
            return
        end if
        call setup(st, body, ee, rt)
        if (present(pulse)) then
            call pulse_validate(pulse, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call pulse_pieces_check(pulse, 'cylinder_roll', stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            beta = 0.0_dp
            if (present(direction)) beta = direction
            if (.not. ieee_is_finite(beta)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'direction = ' &
                               //real_str(beta)//': must be a finite angle (rad)')
                return
            end if
            st%sys%gr%src = RG_PULSE
            st%sys%gr%p = pulse
            if (pulse%kind == PULSE_EXPONENTIAL) st%sys%gr%cexp = exp_consts(pulse%beta)
            st%sys%gr%ux = cos(beta)
            st%sys%gr%uy = sin(beta)
            call pulse_pieces_init(it, pulse)
            call simulate(st, it, no_record, no_record, 0.0_dp, y0, t_grid, hist, run, stat, &
                          errmsg)
        else if (has_rec) then
            if (.not. (present(accel_x) .and. present(accel_y))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel_x, accel_y: ' &
                               //'give both components of the record')
                return
            end if
            if (size(accel_x) /= size(accel_y)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel_y: must have ' &
                               //'the length of accel_x')
                return
            end if
            if (.not. present(dt)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt: the sampling ' &
                               //'step (> 0, s) of the record is required')
                return
            end if
            gu = body%g
            if (present(g_rec)) gu = g_rec
            call record_step_check(accel_x, dt, gu, stat, errmsg, name='accel_x')
            if (stat /= SEISPULSE_SUCCESS) return
            call record_pieces_check(accel_y, stat, errmsg, name='accel_y')
            if (stat /= SEISPULSE_SUCCESS) return
            call record_in_si(accel_x, gu, ax_si, stat, errmsg, name='accel_x')
            if (stat /= SEISPULSE_SUCCESS) return
            call record_in_si(accel_y, gu, ay_si, stat, errmsg, name='accel_y')
            if (stat /= SEISPULSE_SUCCESS) return
            if (real(steps_per_sample, dp) * size(accel_x) &
                    > real(huge(1) - max_steps_default, dp)) then
                st%max_steps = huge(1)
            else
                st%max_steps = max_steps_default + steps_per_sample * size(accel_x)
            end if
            st%sys%gr%src = RG_RECORD
            call record_pieces_init(it, size(accel_x), dt)
            call simulate(st, it, ax_si, ay_si, dt, y0, t_grid, hist, run, stat, errmsg)
        else
            st%sys%gr%src = RG_ZERO
            call simulate(st, it, no_record, no_record, 0.0_dp, y0, t_grid, hist, run, stat, &
                          errmsg)
        end if
    end subroutine cylinder_roll

    !> Name of an output column (ROLL_OUT_*), '' for another index.
    pure function roll_output_name(k) result(name)
        integer, intent(in) :: k  !! column index
        character(len=len_trim(roll_output_name_text(k))) :: name
        name = roll_output_name_text(k)
    end function roll_output_name

    !> roll_output_name(k) padded with blanks.
    pure function roll_output_name_text(k) result(name)
        integer, intent(in) :: k
        character(len=64) :: name
        select case (k)
        case (ROLL_OUT_THETA)
            name = 'theta'
        case (ROLL_OUT_PSI)
            name = 'psi'
        case (ROLL_OUT_SPIN)
            name = 'spin'
        case (ROLL_OUT_THETA_RATE)
            name = 'theta_rate'
        case (ROLL_OUT_PSI_RATE)
            name = 'psi_rate'
        case (ROLL_OUT_SPIN_RATE)
            name = 'spin_rate'
        case (ROLL_OUT_XP)
            name = 'x_contact'
        case (ROLL_OUT_YP)
            name = 'y_contact'
        case (ROLL_OUT_XG)
            name = 'x_g'
        case (ROLL_OUT_YG)
            name = 'y_g'
        case (ROLL_OUT_NORMAL)
            name = 'normal_force'
        case (ROLL_OUT_FRICTION)
            name = 'friction_demand'
        case (ROLL_OUT_ENERGY)
            name = 'energy'
        case default
            name = ''
        end select
    end function roll_output_name_text

    !> Name of a run outcome (ROLL_RUN_*), '' for another code.
    pure function roll_outcome_name(code) result(name)
        integer, intent(in) :: code  !! ROLL_RUN_* code
        character(len=len_trim(roll_outcome_name_text(code))) :: name
        name = roll_outcome_name_text(code)
    end function roll_outcome_name

    !> roll_outcome_name(code) padded with blanks.
    pure function roll_outcome_name_text(code) result(name)
        integer, intent(in) :: code
        character(len=64) :: name
        select case (code)
        case (ROLL_RUN_REST)
            name = 'rest'
        case (ROLL_RUN_NO_UPLIFT)
            name = 'no_uplift'
        case (ROLL_RUN_OVERTURN)
            name = 'overturn'
        case (ROLL_RUN_TIME_LIMIT)
            name = 'time_limit'
        case default
            name = ''
        end select
    end function roll_outcome_name_text

    ! ------------------------------------------------------------------------------
    ! Set-up and checks
    ! ------------------------------------------------------------------------------

    subroutine check_body(body, stat, errmsg)
        type(rocking_body_t), intent(in) :: body
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(body%r)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%r = '//real_str(body%r) &
                           //': must be a finite number > 0 (m)')
        else if (.not. finite_positive(body%h)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%h = '//real_str(body%h) &
                           //': must be a finite number > 0 (m)')
        else if (.not. finite_positive(body%mass)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%mass = ' &
                           //real_str(body%mass)//': must be a finite number > 0 (kg)')
        else if (.not. finite_positive(body%g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%g = '//real_str(body%g) &
                           //': must be a finite number > 0 (m/s^2)')
        else if (.not. finite_positive(body%j_g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%j_g = ' &
                           //real_str(body%j_g)//': must be a finite number > 0 (kg m^2)')
        else if (.not. finite_positive(body%j_axis)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body%j_axis = ' &
                           //real_str(body%j_axis)//': the inertia about the axis must be a ' &
                           //'finite number > 0 (kg m^2); rolling needs it')
        end if
    end subroutine check_body

    subroutine initial_state(y0, stat, errmsg, theta0, psi0, spin0, theta_rate0, psi_rate0, &
                             spin_rate0)
        real(dp), intent(out) :: y0(NY)
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(in), optional :: theta0, psi0, spin0, theta_rate0, psi_rate0, &
                                          spin_rate0
        character(len=12), parameter :: names(6) = [character(len=12) :: 'theta0', 'psi0', &
            'spin0', 'theta_rate0', 'psi_rate0', 'spin_rate0']
        character(len=6), parameter :: units(6) = [character(len=6) :: 'rad', 'rad', 'rad', &
            'rad/s', 'rad/s', 'rad/s']
        integer :: k
        stat = SEISPULSE_SUCCESS
        y0 = 0.0_dp
        if (present(theta0)) y0(1) = theta0
        if (present(psi0)) y0(2) = psi0
        if (present(spin0)) y0(3) = spin0
        if (present(theta_rate0)) y0(4) = theta_rate0
        if (present(psi_rate0)) y0(5) = psi_rate0
        if (present(spin_rate0)) y0(6) = spin_rate0
        if (.not. (in_open(y0(1), -1.0_dp, half_pi) .and. y0(1) >= 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta0 = '//real_str(y0(1)) &
                           //': must be a number in [0, pi/2) (rad)')
            return
        end if
        do k = 2, 6
            if (.not. ieee_is_finite(y0(k))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, trim(names(k))//' = ' &
                               //real_str(y0(k))//': must be a finite number ('//trim(units(k)) &
                               //')')
                return
            end if
        end do
        if (.not. y0(1) > 0.0_dp .and. (abs(y0(5)) > 0.0_dp .or. abs(y0(6)) > 0.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'psi_rate0, spin_rate0: ' &
                           //'must be 0 when theta0 = 0 (the heading of an upright body is ' &
                           //'undefined)')
            return
        end if
        if (.not. y0(1) > 0.0_dp .and. y0(4) < 0.0_dp) then
            ! upright and falling the other way: the same state on the opposite rim point
            y0(2) = y0(2) + pi
            y0(3) = y0(3) - pi
            y0(4) = -y0(4)
        end if
    end subroutine initial_state

    subroutine setup(st, body, e, rtol)
        type(roll_state_t), intent(inout) :: st
        type(rocking_body_t), intent(in) :: body
        real(dp), intent(in) :: e, rtol
        real(dp) :: j_o
        st%sys%r = body%r
        st%sys%h = body%h
        st%sys%m = body%mass
        st%sys%g = body%g
        st%sys%ia = body%j_g
        st%sys%ic = body%j_axis
        st%theta_c = atan2(body%r, body%h)
        st%sys%s_reg = sin(floor_tol * st%theta_c)
        st%big_r = hypot(body%r, body%h)
        j_o = body%j_g + body%mass * st%big_r**2
        st%p = sqrt(body%mass * body%g * st%big_r / j_o)
        st%e = e
        st%thr = body%g * tan(st%theta_c)
        call st%ode%init(NY, rtol, rtol * [st%theta_c, 1.0_dp, 1.0_dp, st%p * st%theta_c, &
                         st%p, st%p, st%big_r * st%theta_c, st%big_r * st%theta_c], st%stat)
    end subroutine setup

    subroutine empty_run(run)
        type(roll_run_t), intent(inout) :: run
        if (allocated(run%t_impacts)) deallocate(run%t_impacts)
        allocate(run%t_impacts(0))
        run%outcome = ROLL_RUN_NO_UPLIFT
        run%t_uplift = ieee_value(1.0_dp, ieee_quiet_nan)
        run%t_lift_off = run%t_uplift
        run%n_impacts = 0
        run%n_floor = 0
        run%theta_max = 0.0_dp
        run%friction_max = 0.0_dp
        run%energy_drift = 0.0_dp
        run%t_end = 0.0_dp
        run%n_steps = 0
    end subroutine empty_run

    ! ------------------------------------------------------------------------------
    ! The event-driven integrator
    ! ------------------------------------------------------------------------------

    subroutine simulate(st, it, ax, ay, dt, y0, t_grid, hist, run, stat, errmsg)
        type(roll_state_t), intent(inout) :: st
        type(piece_iter_t), intent(inout) :: it
        real(dp), intent(in) :: ax(:), ay(:), dt
        real(dp), intent(in) :: y0(NY)
        real(dp), intent(in) :: t_grid(:)
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(piece_t) :: piece
        real(dp) :: t_run
        integer :: src, i, why, kk
        logical :: found

        stat = SEISPULSE_SUCCESS
        if (st%stat /= SEISPULSE_SUCCESS) then
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'cylinder_roll: integrator ' &
                           //'set-up failed (a bug)')
            return
        end if
        allocate(st%tg, source=t_grid)
        st%ng = size(t_grid)
        st%ig = 1
        allocate(st%imp(16))
        st%t = 0.0_dp
        st%y = y0
        st%h = 0.05_dp / st%p
        st%e_ref = ieee_value(1.0_dp, ieee_quiet_nan)
        src = st%sys%gr%src
        if (y0(1) > 0.0_dp .or. y0(4) > 0.0_dp) then
            st%mode = 1
            st%ever_up = .true.
            st%from_zero = .not. y0(1) > 0.0_dp
            run%t_uplift = 0.0_dp
            run%theta_max = y0(1)
        else
            st%mode = 0
            st%y(4:6) = 0.0_dp
        end if
        ! the state before t = 0 is the initial one
        st%sys%gr%src = RG_ZERO
        do while (st%ig <= st%ng)
            if (st%tg(st%ig) > 0.0_dp) exit
            call put_state(st, st%tg(st%ig), st%y, hist(:, st%ig), run)
            st%ig = st%ig + 1
        end do
        st%sys%gr%src = src

        if (src /= RG_ZERO) then
            pieces: do
                call next_piece(it, ax, 'cylinder_roll', piece, found, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                if (.not. found) exit pieces
                call load_piece(st%sys%gr, piece, ay, dt, piece_step(it))
                if (st%t < piece%ta) then
                    ! no excitation before this piece (M&P window)
                    st%sys%gr%src = RG_ZERO
                    call run_segment(st, hist, run, piece%ta)
                    st%sys%gr%src = src
                    if (st%done) exit pieces
                end if
                st%blocked = 0
                call run_segment(st, hist, run, piece%tb)
                if (st%done) exit pieces
            end do pieces
        end if

        if (.not. st%done) then
            ! free motion from now on
            st%sys%gr%src = RG_ZERO
            st%e_ref = ieee_value(1.0_dp, ieee_quiet_nan)
            do kk = 1, 2
                if (st%mode == 0) then
                    call finish_rest(st, hist, run)
                    exit
                end if
                t_run = st%t_lim
                if (st%e >= 1.0_dp .and. st%t_lim >= huge(1.0_dp) .and. never_overturns(st)) then
                    ! perpetual rocking: nothing more to learn without t_max beyond the last
                    ! output time
                    t_run = st%t
                    if (st%ng > 0) t_run = max(st%t, st%tg(st%ng))
                end if
                call advance(st, hist, run, t_run, why)
                if (st%stat /= SEISPULSE_SUCCESS) exit
                select case (why)
                case (WHY_REST)
                    cycle
                case (WHY_CAP)
                    call finish(st, hist, run, ROLL_RUN_OVERTURN)
                case default
                    call finish(st, hist, run, ROLL_RUN_TIME_LIMIT)
                end select
                exit
            end do
        end if
        if (st%stat /= SEISPULSE_SUCCESS .or. st%sys%stat /= SEISPULSE_SUCCESS) then
            if (.not. allocated(st%msg)) st%msg = 'cylinder_roll: the 3x3 solve failed (a bug)'
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, st%msg)
            return
        end if
        run%n_impacts = st%n_imp
        run%n_floor = st%n_floor
        run%n_steps = st%steps
        if (allocated(run%t_impacts)) deallocate(run%t_impacts)
        allocate(run%t_impacts(st%n_imp))
        do i = 1, st%n_imp
            run%t_impacts(i) = st%imp(i)
        end do
    end subroutine simulate

    !> Rest and flights on the current piece up to t_stop.
    subroutine run_segment(st, hist, run, t_stop)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        integer :: kk, why
        do kk = 1, st%max_steps
            if (.not. st%t < t_stop) return
            if (.not. st%t < st%t_lim) then
                call finish(st, hist, run, ROLL_RUN_TIME_LIMIT)
                return
            end if
            if (st%mode == 0) then
                call rest_scan(st, hist, run, t_stop)
                if (st%done .or. st%stat /= SEISPULSE_SUCCESS) then
                    st%done = .true.
                    return
                end if
            else
                call advance(st, hist, run, min(t_stop, st%t_lim), why)
                if (st%stat /= SEISPULSE_SUCCESS) then
                    st%done = .true.
                    return
                end if
                select case (why)
                case (WHY_TOUCH)
                    ! the threshold touched, not exceeded: no uplift that way on this piece
                    st%blocked = 1
                    if (st%sys%gr%src == RG_PULSE) st%blocked = st%dir
                    call set_rest(st, hist, run, st%t)
                case (WHY_CAP)
                    call finish(st, hist, run, ROLL_RUN_OVERTURN)
                    return
                case (WHY_LIMIT)
                    call finish(st, hist, run, ROLL_RUN_TIME_LIMIT)
                    return
                end select
            end if
        end do
        call finish(st, hist, run, ROLL_RUN_TIME_LIMIT)
    end subroutine run_segment

    !> At rest on the current piece: find the uplift, |a_g| > g tan(theta_c)
    !> (doc/rolling.md section 4), or move to t_stop.
    subroutine rest_scan(st, hist, run, t_stop)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        real(dp) :: a_c, a_e, lev, t_u, ax, ay, aq, bq, cq, disc, tau, span, dx, dy, psi_t
        integer :: dir
        logical :: now, up
        character(len=120) :: rmsg
        associate(gr => st%sys%gr)
        up = .false.
        dir = 0
        t_u = st%t
        select case (gr%src)
        case (RG_PULSE)
            a_c = ground_scalar(gr, st%t)
            a_e = gr%ab
            call onset_on_piece(a_c, a_e, st%thr, st%thr, st%blocked, dir, lev, now)
            if (dir /= 0) then
                up = .true.
                if (.not. now) then
                    gr%level = lev
                    rmsg = ''
                    call find_root(gr, st%t, t_stop, t_u, st%stat, rmsg, fa_known=a_c - lev, &
                                   fb_known=a_e - lev)
                    if (st%stat /= SEISPULSE_SUCCESS) then
                        st%msg = 'cylinder_roll: uplift location failed after t = ' &
                                 //real_str(st%t)//': '//trim(rmsg)//' (a bug)'
                        st%stat = SEISPULSE_INTERNAL
                        return
                    end if
                    t_u = min(max(t_u, st%t), t_stop)
                end if
            end if
        case (RG_RECORD)
            if (st%blocked == 0) then
                ! |a(t + tau)|^2 - thr^2 = aq tau^2 + 2 bq tau + cq on the step (a line)
                call ground_vec(gr, st%t, ax, ay)
                aq = gr%sx**2 + gr%sy**2
                bq = ax * gr%sx + ay * gr%sy
                cq = (ax**2 + ay**2) - st%thr**2
                span = t_stop - st%t
                if (cq > 0.0_dp) then
                    up = .true.
                else if (aq > 0.0_dp .and. (aq * span + 2.0_dp * bq) * span + cq > 0.0_dp) then
                    ! the larger root (cq <= 0), in its cancellation-free form
                    disc = sqrt(max(bq**2 - aq * cq, 0.0_dp))
                    if (bq > 0.0_dp) then
                        tau = -cq / (bq + disc)
                    else
                        tau = (disc - bq) / aq
                    end if
                    up = .true.
                    t_u = st%t + min(max(tau, 0.0_dp), span)
                end if
            end if
        end select
        if (.not. up) then
            call fill_rest(st, hist, run, t_stop)
            st%t = t_stop
            return
        end if
        if (t_u > st%t_lim) then
            call fill_rest(st, hist, run, st%t_lim)
            st%t = st%t_lim
            call finish(st, hist, run, ROLL_RUN_TIME_LIMIT)
            return
        end if
        call fill_rest(st, hist, run, t_u)
        st%t = t_u
        ! the rocking plane along a_g, the body leaning away from it: d = a_g/|a_g|
        if (gr%src == RG_PULSE) then
            st%dir = dir
            dx = real(dir, dp) * gr%ux
            dy = real(dir, dp) * gr%uy
        else
            call ground_vec(gr, t_u, dx, dy)
        end if
        psi_t = atan2(-dx, dy)
        st%y(1) = 0.0_dp
        ! upright, the pose is Rz(psi + phi_s): re-aiming psi turns phi_s back
        psi_t = psi_t + 2.0_dp * pi * anint((st%y(2) - psi_t) / (2.0_dp * pi))
        st%y(3) = st%y(3) - (psi_t - st%y(2))
        st%y(2) = psi_t
        st%y(4:6) = 0.0_dp
        st%mode = 1
        st%from_zero = .true.
        st%uplifting = .true.
        if (.not. st%ever_up) then
            st%ever_up = .true.
            run%t_uplift = t_u
        end if
        end associate
    end subroutine rest_scan

    !> Integrate the flight from (t, y) up to t_stop: impacts (restitution, rest), floor
    !> passes, theta = pi/2, output points.
    subroutine advance(st, hist, run, t_stop, why)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        integer, intent(out) :: why
        real(dp) :: hh, t_new, y_new(NY), f_new(NY), err, fac, th0, th1, w0, w1, x_turn, &
                    th_turn, x_ev, yv(NY), fl, fa
        integer :: ev, kk
        logical :: clamped, rejected, turn_min, turn_max, need, planar

        why = WHY_REACHED
        fl = floor_tol * st%theta_c
        call st%sys%rhs(st%t, st%y, st%f)
        if (st%sys%gr%src == RG_ZERO .and. ieee_is_nan(st%e_ref)) &
            st%e_ref = energy(st%sys, st%y)
        rejected = .false.
        do kk = 1, st%max_steps
            if (.not. st%t < t_stop) return
            if (st%steps >= st%max_steps) then
                why = WHY_LIMIT
                return
            end if
            st%steps = st%steps + 1
            ! at most half the fastest time scale of theta: the rocking 1/p, the heading
            ! 1/|psi'| and the nutation A/(C |omega_Z|): one turning point of theta per step
            st%h = min(st%h, 0.5_dp / max(st%p, abs(st%y(5)), st%sys%ic &
                       * abs(st%y(5) + st%y(6) * cos(st%y(1))) / st%sys%ia))
            clamped = .not. st%h < t_stop - st%t
            if (clamped) then
                t_new = t_stop
            else
                t_new = st%t + st%h
            end if
            hh = t_new - st%t
            if (hh < min_step(st, st%t)) then
                if (st%from_zero) then
                    ! no flight of any length leaves the base: not an uplift (WHY_TOUCH), or
                    ! after an impact, rest
                    if (st%uplifting) then
                        why = WHY_TOUCH
                    else
                        call set_rest(st, hist, run, st%t)
                        why = WHY_REST
                    end if
                    return
                else if (clamped) then
                    ! a sliver of a piece below the time resolution: step over it
                    st%t = t_new
                    cycle
                else if (st%y(1) < touch_tol * st%theta_c) then
                    ! a pass too fast for the time resolution near theta = 0: a touch,
                    ! counted as an impact (doc/rolling.md section 4)
                    yv = st%y
                    call impact(st, hist, run, yv, EV_FLOOR, t_stop, why)
                    if (why /= WHY_REACHED) return
                    ! the flight goes on from theta > 0: a fresh step size
                    st%h = 0.05_dp / st%p
                    rejected = .false.
                    cycle
                end if
                why = WHY_LIMIT
                return
            end if
            call st%ode%step(st%sys, st%t, st%y, st%f, hh, t_new, y_new, f_new, err)
            th1 = y_new(1)
            if (.not. (err <= 1.0_dp .and. abs(th1) <= pi .and. all(ieee_is_finite(y_new)))) then
                ! (a blown-up step can pass the error test relative to its own size)
                rejected = .true.
                st%h = hh * ode_dop853_factor(err)
                if (err <= 1.0_dp) st%h = 0.25_dp * hh
                cycle
            end if
            if (st%from_zero .and. .not. th1 > 0.0_dp) then
                ! the first step of a flight must leave the base: shorter
                st%h = 0.25_dp * hh
                cycle
            end if
            fac = ode_dop853_factor(err)
            if (rejected) fac = min(fac, 1.0_dp)
            rejected = .false.
            st%from_zero = .false.
            st%uplifting = .false.
            th0 = st%y(1)
            w0 = st%y(4)
            w1 = y_new(4)
            ! a motion in a fixed plane (psi' = phi_s' = 0 exactly, section 3 of
            ! doc/rolling.md) crosses theta = 0 smoothly: no floor rule for it
            planar = .not. (abs(st%y(5)) > 0.0_dp .or. abs(st%y(6)) > 0.0_dp .or. &
                            abs(y_new(5)) > 0.0_dp .or. abs(y_new(6)) > 0.0_dp)
            turn_max = w0 >= 0.0_dp .and. w1 < 0.0_dp
            turn_min = w0 < 0.0_dp .and. w1 > 0.0_dp
            need = th1 < fl .or. th1 >= half_pi .or. turn_max .or. turn_min
            if (st%ig <= st%ng) need = need .or. st%tg(st%ig) <= t_new
            ev = EV_NONE
            x_ev = 1.0_dp
            if (need) then
                call st%ode%dense_setup(st%sys, st%t, st%y, st%f, hh, y_new, f_new)
                x_turn = 0.0_dp
                th_turn = th0
                if (turn_max .or. turn_min) then
                    fa = w0
                    if (.not. abs(w0) > 0.0_dp) fa = tiny(fa)
                    call locate(st, 4, 0.0_dp, 0.0_dp, 1.0_dp, fa, w1, x_turn)
                    if (st%stat /= SEISPULSE_SUCCESS) return
                    th_turn = st%ode%dense%component(1, x_turn)
                end if
                if (turn_max) then
                    run%theta_max = max(run%theta_max, th_turn)
                    if (th_turn >= half_pi) then
                        ev = EV_CAP
                        call locate(st, 1, half_pi, 0.0_dp, x_turn, th0 - half_pi, &
                                    th_turn - half_pi, x_ev)
                    else if (th1 < fl .and. .not. planar .and. th_turn > fl) then
                        ev = EV_FLOOR
                        call locate(st, 1, fl, x_turn, 1.0_dp, th_turn - fl, th1 - fl, x_ev)
                    else if (th1 <= 0.0_dp) then
                        ! (th_turn >= th0 >= 0; th0 = 0 only on a first step, which rises)
                        ev = EV_IMPACT
                        call locate(st, 1, 0.0_dp, x_turn, 1.0_dp, th_turn, th1, x_ev)
                    end if
                else if (turn_min) then
                    if (th0 <= fl) then
                        ev = EV_FLOOR
                        x_ev = 0.0_dp
                    else if (th_turn <= 0.0_dp) then
                        ev = EV_IMPACT
                        call locate(st, 1, 0.0_dp, 0.0_dp, x_turn, th0, th_turn, x_ev)
                    else if (th_turn < fl) then
                        ev = EV_FLOOR
                        call locate(st, 1, fl, 0.0_dp, x_turn, th0 - fl, th_turn - fl, x_ev)
                    end if
                else if (th1 < fl .and. .not. planar .and. th0 > fl) then
                    ev = EV_FLOOR
                    call locate(st, 1, fl, 0.0_dp, 1.0_dp, th0 - fl, th1 - fl, x_ev)
                else if (th1 <= 0.0_dp) then
                    ev = EV_IMPACT
                    call locate(st, 1, 0.0_dp, 0.0_dp, 1.0_dp, th0, th1, x_ev)
                else if (th1 >= half_pi) then
                    ev = EV_CAP
                    call locate(st, 1, half_pi, 0.0_dp, 1.0_dp, th0 - half_pi, th1 - half_pi, &
                                x_ev)
                end if
                if (st%stat /= SEISPULSE_SUCCESS) return
            end if
            if (ev == EV_NONE) run%theta_max = max(run%theta_max, th1)
            ! output points inside the step (up to the event)
            do while (st%ig <= st%ng)
                if (ev == EV_NONE) then
                    if (st%tg(st%ig) > t_new) exit
                else
                    if (st%tg(st%ig) > st%t + x_ev * hh) exit
                end if
                call st%ode%value(min(max((st%tg(st%ig) - st%t) / hh, 0.0_dp), 1.0_dp), yv)
                call put_state(st, st%tg(st%ig), yv, hist(:, st%ig), run)
                st%ig = st%ig + 1
            end do
            if (clamped) then
                st%h = max(st%h, hh * fac)
            else
                st%h = hh * fac
            end if
            if (ev == EV_NONE) then
                call step_end(st, run, t_new, y_new)
                st%t = t_new
                st%y = y_new
                st%f = f_new
                cycle
            end if
            call st%ode%value(x_ev, yv)
            if (x_ev < 1.0_dp) then
                st%t = st%t + x_ev * hh
            else
                st%t = t_new
            end if
            if (ev == EV_CAP) then
                yv(1) = half_pi
                st%y = yv
                run%theta_max = half_pi
                why = WHY_CAP
                return
            end if
            call impact(st, hist, run, yv, ev, t_stop, why)
            if (why /= WHY_REACHED) return
        end do
        why = WHY_LIMIT
    end subroutine advance

    !> Impact at st%t in the state yv (doc/rolling.md section 4): the contact to the
    !> opposite rim point (psi + pi), theta' -> e |theta'|, psi' and phi_s' kept; theta = 0
    !> (EV_IMPACT) or kept (floor, touch). Then rest if the next flight is negligible.
    subroutine impact(st, hist, run, yv, ev, t_stop, why)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(inout) :: yv(NY)
        integer, intent(in) :: ev
        real(dp), intent(in) :: t_stop
        integer, intent(out) :: why
        real(dp), allocatable :: tmp(:)
        real(dp) :: acc0, amp, t_r
        why = WHY_REACHED
        st%n_imp = st%n_imp + 1
        if (ev /= EV_IMPACT) st%n_floor = st%n_floor + 1
        if (st%n_imp > size(st%imp)) then
            allocate(tmp(2 * size(st%imp)))
            tmp(1:size(st%imp)) = st%imp
            call move_alloc(tmp, st%imp)
        end if
        st%imp(st%n_imp) = st%t
        ! (L.11)
        if (ev == EV_IMPACT) yv(1) = 0.0_dp
        ! Rz(psi) Rx(-theta) Rz(phi_s) = Rz(psi + pi) Rx(theta) Rz(phi_s - pi): the body
        ! keeps its pose (psi + phi_s continuous)
        yv(2) = yv(2) + pi
        yv(3) = yv(3) - pi
        yv(4) = st%e * abs(yv(4))
        st%y = yv
        call st%sys%rhs(st%t, st%y, st%f)
        if (st%sys%gr%src == RG_ZERO) st%e_ref = energy(st%sys, st%y)
        acc0 = st%f(4)
        if (ev /= EV_IMPACT .and. rocking_energy(st) <= rest_tol * st%theta_c * st%sys%m &
                * st%sys%g * st%sys%r) then
            ! a floor pass left (almost) no rocking, only the turn round the rim at theta
            ! ~ theta_floor: rest
            call set_rest(st, hist, run, st%t)
            why = WHY_REST
            return
        end if
        if (.not. acc0 > 0.0_dp) then
            ! pushed back onto the base: the next flight rises theta'^2/(2|theta''|)
            if (abs(acc0) > 0.0_dp) then
                amp = 0.5_dp * st%y(4)**2 / abs(acc0)
            else if (abs(st%y(4)) > 0.0_dp) then
                amp = huge(amp)
            else
                amp = 0.0_dp
            end if
            if (amp <= rest_tol * st%theta_c) then
                ! rest (ends a Zeno sequence): flights tau, e tau, ... sum tau/(1 - e)
                t_r = st%t
                if (abs(acc0) > 0.0_dp .and. st%e < 1.0_dp) &
                    t_r = st%t + 2.0_dp * abs(st%y(4)) / abs(acc0) / (1.0_dp - st%e)
                call set_rest(st, hist, run, min(t_r, t_stop))
                why = WHY_REST
                return
            end if
            st%h = min(st%h, 0.5_dp * abs(st%y(4)) / abs(acc0))
        end if
        ! from theta = 0 the first step must rise (a floor pass keeps theta > 0)
        st%from_zero = .not. st%y(1) > 0.0_dp
        st%uplifting = .false.
    end subroutine impact

    !> Root of y(comp) - level on the dense output in [xa, xb] (fa, fb the values there).
    subroutine locate(st, comp, level, xa, xb, fa, fb, x)
        type(roll_state_t), intent(inout) :: st
        integer, intent(in) :: comp
        real(dp), intent(in) :: level, xa, xb, fa, fb
        real(dp), intent(out) :: x
        character(len=120) :: rmsg
        rmsg = ''
        call st%ode%locate(comp, 1.0_dp, level, xa, xb, fa, fb, x, st%stat, rmsg)
        if (st%stat /= SEISPULSE_SUCCESS) then
            st%msg = 'cylinder_roll: event location failed after t = '//real_str(st%t)//': ' &
                     //trim(rmsg)//' (a bug)'
            st%stat = SEISPULSE_INTERNAL
            st%done = .true.
        end if
    end subroutine locate

    !> After an accepted step: friction demand, lift-off, energy drift in free motion.
    subroutine step_end(st, run, t, y)
        type(roll_state_t), intent(inout) :: st
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: t, y(NY)
        real(dp) :: col(ROLL_NOUT)
        real(dp) :: e_rock
        call put_state(st, t, y, col, run)
        if (st%sys%gr%src == RG_ZERO .and. ieee_is_finite(st%e_ref)) then
            ! relative to the energy above rest at the start of the flight (L.9)
            e_rock = st%e_ref - st%sys%m * st%sys%g * st%sys%h
            if (e_rock > 0.0_dp) run%energy_drift = max(run%energy_drift, &
                abs(col(ROLL_OUT_ENERGY) - st%e_ref) / e_rock)
        end if
    end subroutine step_end

    !> The output columns of a rocking state y at t (and the run's friction and lift-off).
    subroutine put_state(st, t, y, col, run)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(in) :: t, y(NY)
        real(dp), intent(out) :: col(:)
        type(roll_run_t), intent(inout) :: run
        real(dp) :: qdd(3), vg(2), rf(3), rho_d
        if (st%mode == 0) then
            call put_rest(st, t, y, col, run)
            return
        end if
        call kinematics(st%sys, t, y, qdd, vg, rf)
        col(1:6) = y(1:6)
        rho_d = st%sys%r * cos(y(1)) - st%sys%h * sin(y(1))
        col(ROLL_OUT_XP) = y(7) + rho_d * sin(y(2))
        col(ROLL_OUT_YP) = y(8) - rho_d * cos(y(2))
        col(ROLL_OUT_XG) = y(7)
        col(ROLL_OUT_YG) = y(8)
        call force_columns(rf, t, col, run)
        col(ROLL_OUT_ENERGY) = energy(st%sys, y)
    end subroutine put_state

    !> N and |F_t|/N from the contact force rf (N, on n, d, Z); lift-off if N <= 0.
    subroutine force_columns(rf, t, col, run)
        real(dp), intent(in) :: rf(3), t
        real(dp), intent(inout) :: col(:)
        type(roll_run_t), intent(inout) :: run
        col(ROLL_OUT_NORMAL) = rf(3)
        if (rf(3) > 0.0_dp) then
            col(ROLL_OUT_FRICTION) = hypot(rf(1), rf(2)) / rf(3)
            run%friction_max = max(run%friction_max, col(ROLL_OUT_FRICTION))
        else
            col(ROLL_OUT_FRICTION) = ieee_value(1.0_dp, ieee_quiet_nan)
            if (ieee_is_nan(run%t_lift_off)) run%t_lift_off = t
        end if
    end subroutine force_columns

    !> The output columns at rest (base flat on the ground; the contact point reported is
    !> the rim point at the heading psi): N = m g, |F_t| = m |a_g|.
    subroutine put_rest(st, t, y, col, run)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(in) :: t, y(NY)
        real(dp), intent(out) :: col(:)
        type(roll_run_t), intent(inout) :: run
        real(dp) :: ax, ay, cp, sp
        call ground_vec(st%sys%gr, t, ax, ay)
        cp = cos(y(2))
        sp = sin(y(2))
        col(1:6) = 0.0_dp
        col(ROLL_OUT_PSI) = y(2)
        col(ROLL_OUT_SPIN) = y(3)
        col(ROLL_OUT_XP) = y(7) + st%sys%r * sp
        col(ROLL_OUT_YP) = y(8) - st%sys%r * cp
        col(ROLL_OUT_XG) = y(7)
        col(ROLL_OUT_YG) = y(8)
        call force_columns(st%sys%m * [ax * cp + ay * sp, -ax * sp + ay * cp, st%sys%g], t, &
                           col, run)
        col(ROLL_OUT_ENERGY) = st%sys%m * st%sys%g * st%sys%h
    end subroutine put_rest

    !> Output points up to tt while at rest.
    subroutine fill_rest(st, hist, run, tt)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: tt
        do while (st%ig <= st%ng)
            if (st%tg(st%ig) > tt) exit
            call put_rest(st, st%tg(st%ig), st%y, hist(:, st%ig), run)
            st%ig = st%ig + 1
        end do
    end subroutine fill_rest

    !> Back at rest at tt (output points up to tt: the rest state).
    subroutine set_rest(st, hist, run, tt)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        real(dp), intent(in) :: tt
        st%mode = 0
        st%y(1) = 0.0_dp
        st%y(4:6) = 0.0_dp
        call fill_rest(st, hist, run, tt)
        st%t = max(st%t, tt)
        st%t_rest = st%t
        st%from_zero = .false.
        st%uplifting = .false.
        st%e_ref = ieee_value(1.0_dp, ieee_quiet_nan)
    end subroutine set_rest

    subroutine finish_rest(st, hist, run)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        if (st%ever_up) then
            call finish(st, hist, run, ROLL_RUN_REST)
        else
            call finish(st, hist, run, ROLL_RUN_NO_UPLIFT)
        end if
    end subroutine finish_rest

    !> End of the run: the outcome, and the output points after it.
    subroutine finish(st, hist, run, outcome)
        type(roll_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(roll_run_t), intent(inout) :: run
        integer, intent(in) :: outcome
        real(dp) :: col(ROLL_NOUT), nan
        st%done = .true.
        run%outcome = outcome
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        select case (outcome)
        case (ROLL_RUN_NO_UPLIFT)
            run%t_end = 0.0_dp
            call fill_rest(st, hist, run, huge(1.0_dp))
        case (ROLL_RUN_REST)
            run%t_end = st%t_rest
            call fill_rest(st, hist, run, huge(1.0_dp))
        case (ROLL_RUN_OVERTURN)
            run%t_end = st%t
            ! on its side: frozen, no contact model any more
            col(1:6) = st%y(1:6)
            col(ROLL_OUT_XP) = st%y(7) - st%sys%h * sin(st%y(2))
            col(ROLL_OUT_YP) = st%y(8) + st%sys%h * cos(st%y(2))
            col(ROLL_OUT_XG) = st%y(7)
            col(ROLL_OUT_YG) = st%y(8)
            col(1) = half_pi
            col(4:6) = 0.0_dp
            col(ROLL_OUT_NORMAL:ROLL_OUT_ENERGY) = nan
            do while (st%ig <= st%ng)
                hist(:, st%ig) = col
                st%ig = st%ig + 1
            end do
        case default
            run%t_end = st%t
            do while (st%ig <= st%ng)
                hist(:, st%ig) = nan
                st%ig = st%ig + 1
            end do
        end select
    end subroutine finish

    !> After the excitation, E < m g R with theta < theta_c: the body can never pass
    !> theta_c (V <= m g R, flights keep E, impacts lower it; doc/rolling.md section 4).
    pure function never_overturns(st) result(safe)
        type(roll_state_t), intent(in) :: st
        logical :: safe
        safe = st%y(1) < st%theta_c .and. energy(st%sys, st%y) < st%sys%m * st%sys%g * st%big_r
    end function never_overturns

    !> Energy of the rocking left after a floor pass (J): the theta' part
    !> J_n theta'^2/2 (J_n = n.I_P n, the inertia about the rim tangent through P), the
    !> potential being the floor's (theta = theta_floor is kept at a floor pass). The turn
    !> about the vertical and the run of the contact round the rim are not rocking
    !> (the rest rule of the floor passes, doc/rolling.md section 4).
    pure function rocking_energy(st) result(en)
        type(roll_state_t), intent(in) :: st
        real(dp) :: en
        real(dp) :: s, c, j_n(3)
        s = sin(st%y(1))
        c = cos(st%y(1))
        j_n = inertia_p(st%sys, [0.0_dp, -s, c], [0.0_dp, st%sys%r * c - st%sys%h * s, &
                        st%sys%r * s + st%sys%h * c], [1.0_dp, 0.0_dp, 0.0_dp])
        en = 0.5_dp * j_n(1) * st%y(4)**2
    end function rocking_energy

    pure function min_step(st, t) result(h)
        type(roll_state_t), intent(in) :: st
        real(dp), intent(in) :: t
        real(dp) :: h
        h = 16.0_dp * epsilon(t) * max(abs(t), 1.0e-3_dp / st%p)
    end function min_step

    ! ------------------------------------------------------------------------------
    ! Equations of motion (doc/rolling.md section 2)
    ! ------------------------------------------------------------------------------

    !> The right-hand side for seispulse_ode: (rates, accelerations (L.6), v_G (L.3)).
    subroutine roll_rhs(self, t, y, dydt)
        class(roll_ode_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        real(dp) :: qdd(3), vg(2), d(NY)
        call kinematics(self, t, y, qdd, vg)
        d = [y(4), y(5), y(6), qdd(1), qdd(2), qdd(3), vg(1), vg(2)]
        dydt(1:NY) = d
    end subroutine roll_rhs

    !> Accelerations (theta'', psi'', phi_s'') from the moment equation about the contact
    !> point (L.4)-(L.7), the velocity of G on the ground (L.3), and optionally the
    !> contact force (L.8) on (n, d, Z) (N). Vectors on the triad (n, d, Z), d = Z x n.
    subroutine kinematics(sys, t, y, qdd, vg, rf)
        class(roll_ode_t), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: qdd(3)                !! (rad/s^2)
        real(dp), intent(out) :: vg(2)                 !! v_G on the ground axes (m/s)
        real(dp), intent(out), optional :: rf(3)       !! contact force (N)
        real(dp) :: s, c, sp, cp, thd, psd, phd, e3(3), rho(3), om(3), omc(3), w0(3), ax, ay
        real(dp) :: an, ad, rdot(3), vt(3), v(3), wd(3), ag(3)
        integer :: stat
        s = sin(y(1))
        c = cos(y(1))
        sp = sin(y(2))
        cp = cos(y(2))
        thd = y(4)
        psd = y(5)
        phd = y(6)
        e3 = [0.0_dp, -s, c]                                          ! (L.1)
        rho = [0.0_dp, sys%r * c - sys%h * s, sys%r * s + sys%h * c]  ! (L.1)
        om = [thd, -phd * s, psd + phd * c]                           ! (L.2)
        omc = [thd, 0.0_dp, psd]                                      ! (L.2)
        w0 = [phd * psd * s, thd * psd - phd * thd * c, -phd * thd * s]  ! (L.5)
        call ground_vec(sys%gr, t, ax, ay)
        an = ax * cp + ay * sp
        ad = -ax * sp + ay * cp
        ! a component across the rocking plane at the rounding level of a_g is 0: a motion
        ! in a fixed plane stays in it (the 1/sin(theta) of (L.7) would amplify it)
        if (abs(an) <= 16.0_dp * epsilon(an) * (abs(ax) + abs(ay))) an = 0.0_dp
        rdot = cross(omc, rho)
        ! velocity terms of (L.4), moved to the right
        vt = inertia_g(sys, e3, w0) + cross(om, inertia_g(sys, e3, om)) &
            + sys%m * (cross(rho, cross(w0, rho)) + cross(rho, cross(om, rdot)))
        sys%vec = cross(rho, -sys%m * [an, ad, sys%g]) - vt
        ! (L.6): unknowns theta'', psi'' + cos(theta) phi_s'', sin(theta) phi_s''
        sys%mat(:, 1) = inertia_p(sys, e3, rho, [1.0_dp, 0.0_dp, 0.0_dp])
        sys%mat(:, 2) = inertia_p(sys, e3, rho, [0.0_dp, 0.0_dp, 1.0_dp])
        sys%mat(:, 3) = -inertia_p(sys, e3, rho, [0.0_dp, 1.0_dp, 0.0_dp])
        call solve_linear_inplace(sys%mat, sys%vec, sys%ipiv, stat)
        if (stat /= SEISPULSE_SUCCESS) then
            sys%stat = stat
            sys%vec = 0.0_dp
        end if
        qdd(1) = sys%vec(1)
        ! phi_s'' = b/sin(theta) (L.7); below the floor, |sin(theta)| < s_reg, the ramp
        ! b sin(theta)/s_reg^2 (continuous there) keeps it finite where a flight starts
        if (abs(s) >= sys%s_reg) then
            qdd(3) = sys%vec(3) / s
        else
            qdd(3) = sys%vec(3) * s / sys%s_reg**2
        end if
        qdd(2) = sys%vec(2) - c * qdd(3)                              ! (L.7)
        v = cross(om, rho)                                            ! (L.3)
        vg = [v(1) * cp - v(2) * sp, v(1) * sp + v(2) * cp]
        if (present(rf)) then
            wd = [sys%vec(1), -sys%vec(3), sys%vec(2)] + w0            ! omega' (L.5)
            ag = cross(wd, rho) + cross(om, rdot)
            rf = sys%m * (ag + [an, ad, sys%g])                       ! (L.8)
        end if
    end subroutine kinematics

    !> Kinetic + potential energy in the ground frame (L.9) (J).
    pure function energy(sys, y) result(en)
        class(roll_ode_t), intent(in) :: sys
        real(dp), intent(in) :: y(:)
        real(dp) :: en
        real(dp) :: s, c, e3(3), rho(3), om(3), v(3)
        s = sin(y(1))
        c = cos(y(1))
        e3 = [0.0_dp, -s, c]
        rho = [0.0_dp, sys%r * c - sys%h * s, sys%r * s + sys%h * c]
        om = [y(4), -y(6) * s, y(5) + y(6) * c]
        v = cross(om, rho)
        en = 0.5_dp * sys%m * dot_product(v, v) + 0.5_dp * dot_product(om, inertia_g(sys, e3, om)) &
             + sys%m * sys%g * rho(3)
    end function energy

    !> I_G x = A x + (C - A)(e3.x) e3.
    pure function inertia_g(sys, e3, x) result(ix)
        class(roll_ode_t), intent(in) :: sys
        real(dp), intent(in) :: e3(3), x(3)
        real(dp) :: ix(3)
        ix = sys%ia * x + (sys%ic - sys%ia) * dot_product(e3, x) * e3
    end function inertia_g

    !> I_P x = I_G x + m rho x (x x rho) = I_G x + m (|rho|^2 x - (rho.x) rho).
    pure function inertia_p(sys, e3, rho, x) result(ix)
        class(roll_ode_t), intent(in) :: sys
        real(dp), intent(in) :: e3(3), rho(3), x(3)
        real(dp) :: ix(3)
        ix = inertia_g(sys, e3, x) + sys%m * (dot_product(rho, rho) * x &
                                              - dot_product(rho, x) * rho)
    end function inertia_p

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    ! ------------------------------------------------------------------------------
    ! Ground acceleration
    ! ------------------------------------------------------------------------------

    !> The pulse's a(t) (m/s^2) on the current piece (the limit from inside at its end).
    pure function ground_scalar(gr, t) result(a)
        type(roll_ground_t), intent(in) :: gr
        real(dp), intent(in) :: t
        real(dp) :: a
        if (t >= gr%tb) then
            a = gr%ab
        else
            a = pulse_accel(gr%p, t, gr%cexp)
        end if
    end function ground_scalar

    !> The ground acceleration vector (m/s^2) at t on the current piece.
    pure subroutine ground_vec(gr, t, ax, ay)
        type(roll_ground_t), intent(in) :: gr
        real(dp), intent(in) :: t
        real(dp), intent(out) :: ax, ay
        real(dp) :: a
        select case (gr%src)
        case (RG_PULSE)
            a = ground_scalar(gr, t)
            ax = a * gr%ux
            ay = a * gr%uy
        case (RG_RECORD)
            if (t >= gr%tb) then
                ax = gr%abx
                ay = gr%aby
            else
                ax = gr%ax0 + gr%sx * (t - gr%ta)
                ay = gr%ay0 + gr%sy * (t - gr%ta)
            end if
        case default
            ax = 0.0_dp
            ay = 0.0_dp
        end select
    end subroutine ground_vec

    !> Make a piece the current one; on a record, `piece` is step i of accel_x (the
    !> iterator's record) and the same step of accel_y comes from record_step.
    pure subroutine load_piece(gr, piece, ay, dt, i)
        type(roll_ground_t), intent(inout) :: gr
        type(piece_t), intent(in) :: piece
        real(dp), intent(in) :: ay(:), dt
        integer, intent(in) :: i   !! the record step (piece_step), unused for a pulse
        type(piece_t) :: py
        gr%ta = piece%ta
        gr%tb = piece%tb
        gr%ab = piece%ab
        if (gr%src == RG_RECORD) then
            py = record_step(ay, i, dt)
            gr%ax0 = piece%aa
            gr%ay0 = py%aa
            gr%abx = piece%ab
            gr%aby = py%ab
            gr%sx = piece%slope
            gr%sy = py%slope
        end if
    end subroutine load_piece

    function ground_eval(self, x) result(y)
        class(roll_ground_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        y = ground_scalar(self, x) - self%level
    end function ground_eval

end module seispulse_cylinder_roll
