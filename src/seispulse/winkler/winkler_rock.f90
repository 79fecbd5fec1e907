!> Planar rocking of a rigid cylinder or block on tensionless Winkler springs and dashpots
!> ([KH91] circle, [KSR86] block; doc/winkler.md section "Dynamics", (W.30)-(W.59)).
!>
!> Model. Two degrees of freedom: the settlement v of the base centre (m, + down; the
!> centre does not slide) and the tilt theta (rad; theta > 0 lifts the s > 0 side). A base
!> point at s (m, along the rocking diameter from the centre, |s| <= r) penetrates
!>     delta(s) = v - s sin(theta),  delta'(s) = v' - s cos(theta) theta'       (W.30)
!> and the soil pushes up with the pressure q = max(0, k delta + c delta') where delta > 0
!> (0 elsewhere; k in N/m^3, c in N s/m^3) on the projected area dA = 2 w(s) cos(theta) ds,
!> w(s) = sqrt(r^2 - s^2) (circle) or alpha (rectangle, half-length out of plane) (W.31):
!>     N = C (A_q m0 - B_q m1),  M = C^2 (A_q m1 - B_q m2)                      (W.34)
!> with C = cos(theta), q = A_q - B_q s, A_q = k v + c v', B_q = k sin(theta) + c C theta'
!> and m_j = integral s^j 2 w ds over the active interval [s_a, s_b] (delta > 0 and q > 0
!> within [-r, r], an interval whose ends are edges or roots of the two linear forms),
!> from seispulse_winkler_contact's strip_moments; each end enters by its distances to the
!> two edges, formed from the values of the linear form at the edges (no cancellation
!> beyond that of the edge penetration itself) (W.33). Equations of motion (Lagrange,
!> doc/winkler.md (W.36)-(W.38)), a_g the ground acceleration (m/s^2):
!>     m (v'' + h S theta'' + h C theta'^2) = m g - N
!>     I_O theta'' + m h S v'' = m g h S + M + m a_g h C,   I_O = J_G + m h^2.
!> With k_method = K_VARYING, k is seispulse_winkler's varying_modulus of the geometric
!> contact width b (the width of delta > 0 alone: it depends on (v, theta) only, so the
!> contact set is explicit: b first, then k(b), then the pressure) (W.35).
!> The state carries two more integrals: the work done on the foundation F (J, F' = N v'
!> - M theta') and the input work W_in (J, W_in' = m a_g h C theta') (W.40), so that
!> E = T + V_g + U (kinetic, gravity m g z_G, springs U = integral k delta^2/2 dA) and the
!> dissipated D = F - (U - U_0) satisfy E + D = E_0 + W_in up to the integration error
!> (W.41): the energy check of a run.
!>
!> Method. Radau IIA of order 5 (seispulse_radau, [HW96]) with the exact Jacobian of the
!> model (`jacobian`, (W.44)-(W.47)); steps end on the pieces of the excitation
!> (seispulse_pieces), at most 0.5/p long (p of the rigid body). Events are located on the
!> dense output by Brent's method: the edges' contact (delta(+-r) = 0: uplift begins or
!> ends at an edge, complete lift-off, touch-down), the pressure's sign at the edges
!> (q(+-r) = 0, with c > 0), theta = 0 (an impact when an edge lifted since the previous
!> crossing), |theta| = theta_overturn and |theta| = pi/2. Each step is searched at its
!> ends, at three interior points of the dense output, and at the turning points of the
!> event functions found between them (W.50). A rejected step (error or Newton failure)
!> shrinks h; a bounded budget of steps ends the run with WR_RUN_TIME_LIMIT.
!> Overturning (W.52): |theta| reaches pi/2, or after the excitation |theta| is beyond
!> model%theta_overturn and moving away. After the excitation, with constant k, a total
!> energy below 95 % of the mountain-pass barrier U_min(theta_overturn) - U_min(0) decides
!> that the body stays (the energy criterion (W.53)-(W.55); not a strict proof, because the
!> pressure on the projected area is not conservative: see the margin there).
module seispulse_winkler_rock
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan, ieee_value, &
                                             ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive, finite_at_least, in_closed, in_open, outside, &
                                check_ascending_times
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_special, only: pi
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_ode, only: ode_system
    use seispulse_radau, only: ode_radau5_t, ode_radau5_factor
    use seispulse_pulses, only: pulse_t, pulse_validate, pulse_accel, exp_consts_t, exp_consts, &
                                pulse_kind_name, pulse_end_time, PULSE_EXPONENTIAL, PULSE_HALF_SINE, &
                                PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, PULSE_RECTANGULAR, &
                                PULSE_TRIANGULAR, PULSE_RICKER, ricker_x_cut
    use seispulse_pieces, only: piece_t, piece_iter_t, pulse_pieces_check, record_step_check, &
                                record_in_si, pulse_pieces_init, record_pieces_init, next_piece
    use seispulse_cylinder, only: rocking_body_t, BODY_BLOCK, MAP_AXES_DIMENSIONLESS, &
                                  MAP_AXES_DIMENSIONAL
    use seispulse_winkler_contact, only: strip_moments, FOOTING_CIRCLE, FOOTING_RECTANGLE
    use seispulse_winkler, only: K_CONSTANT, K_VARYING, AXIS_LONG, AXIS_SHORT, varying_modulus, &
                                 winkler_pushover, block_winkler_pushover, winkler_pushover_t
    implicit none
    private

    public :: winkler_model_t, winkler_run_t, winkler_model, winkler_rock
    public :: winkler_overturning_map, winkler_outcome_name, winkler_output_name
    public :: DAMP_ROCKING, DAMP_VERTICAL
    public :: WR_OUT_V, WR_OUT_THETA, WR_OUT_V_RATE, WR_OUT_THETA_RATE, WR_OUT_WIDTH, &
              WR_OUT_NORMAL, WR_OUT_MOMENT, WR_OUT_ACCEL, WR_OUT_ENERGY, WR_OUT_WORK, &
              WR_OUT_DISSIPATED, WR_NOUT
    public :: WR_RUN_SAFE, WR_RUN_OVERTURN_NO_IMPACT, WR_RUN_OVERTURN_ONE_IMPACT, &
              WR_RUN_OVERTURN_IMPACTS, WR_RUN_TIME_LIMIT
    public :: winkler_contact_forces, winkler_rhs_jacobian, winkler_barrier

    integer, parameter :: DAMP_ROCKING = 1   !! c = 2 xi I_O omega_r/I, omega_r^2 = (k I - m g h)/I_O
    integer, parameter :: DAMP_VERTICAL = 2  !! c = 2 xi sqrt(k m/A)

    integer, parameter :: WR_OUT_V = 1            !! settlement of the base centre (m, + down)
    integer, parameter :: WR_OUT_THETA = 2        !! tilt (rad); > 0 lifts the s > 0 side of
                                                  !! the base (doc/winkler.md section 9.1)
    integer, parameter :: WR_OUT_V_RATE = 3       !! v' (m/s)
    integer, parameter :: WR_OUT_THETA_RATE = 4   !! theta' (rad/s)
    integer, parameter :: WR_OUT_WIDTH = 5        !! geometric contact width (m)
    integer, parameter :: WR_OUT_NORMAL = 6       !! soil reaction N (N)
    integer, parameter :: WR_OUT_MOMENT = 7       !! foundation moment about the base centre
                                                  !! (N m), in the sense of theta: restoring,
                                                  !! so of the opposite sign to theta
    integer, parameter :: WR_OUT_ACCEL = 8        !! ground acceleration a_g (m/s^2); a_g > 0
                                                  !! drives theta > 0
    integer, parameter :: WR_OUT_ENERGY = 9       !! kinetic + gravity + spring energy (J);
                                                  !! gravity m g (h cos theta - v), zero at
                                                  !! the ground surface: W (h - v_static/2)
                                                  !! at rest
    integer, parameter :: WR_OUT_WORK = 10        !! input work of the ground motion (J)
    integer, parameter :: WR_OUT_DISSIPATED = 11  !! energy absorbed by the foundation (J):
                                                  !! contact work - spring energy: the
                                                  !! dashpots and the tension cut-off, plus
                                                  !! the exchange of the projected-area
                                                  !! pressure (W.53) (can be briefly < 0) and,
                                                  !! with K_VARYING, the work of k(b)
    integer, parameter :: WR_NOUT = 11            !! number of output columns

    integer, parameter :: WR_RUN_SAFE = 0                 !! standing: the energy criterion, or the map's window
    integer, parameter :: WR_RUN_OVERTURN_NO_IMPACT = 1   !! overturned without an impact
    integer, parameter :: WR_RUN_OVERTURN_ONE_IMPACT = 2  !! overturned after one impact
    integer, parameter :: WR_RUN_OVERTURN_IMPACTS = 3     !! overturned after more impacts
    integer, parameter :: WR_RUN_TIME_LIMIT = 4           !! t_max or the step budget first

    !> A rigid body on a tensionless Winkler foundation (build it with winkler_model).
    type :: winkler_model_t
        type(rocking_body_t) :: body         !! mass, h, j_g, g, rigid theta_c and p
        integer :: footing = FOOTING_CIRCLE  !! FOOTING_CIRCLE or FOOTING_RECTANGLE
        real(dp) :: r = 1.0_dp               !! radius, or half-width b (rectangle) (m)
        real(dp) :: alpha = 0.0_dp           !! half-length of the rectangle (m); circle: 0
        real(dp) :: k = 1.0_dp               !! Winkler modulus (N/m^3), full contact
        real(dp) :: c = 0.0_dp               !! dashpot constant (N s/m^3)
        integer :: k_method = K_CONSTANT     !! K_CONSTANT or K_VARYING
        real(dp) :: theta_overturn = 0.0_dp  !! static overturning angle (rad), NaN: none
        integer :: reading = AXIS_LONG       !! shape-factor reading of the varying k (circle)
        real(dp) :: area = 1.0_dp            !! base area A (m^2)
        real(dp) :: inertia = 1.0_dp         !! second moment I of the base (m^4)
        real(dp) :: v_static = 0.0_dp        !! static settlement W/(k A) (m)
    end type winkler_model_t

    !> Summary of a run.
    type :: winkler_run_t
        integer :: outcome = WR_RUN_TIME_LIMIT      !! one of the WR_RUN_* codes
        integer :: n_impacts = 0                    !! theta = 0 crossings after an uplift
        real(dp), allocatable :: t_impacts(:)       !! their times (s)
        real(dp), allocatable :: impact_normal_peak(:)  !! peak N of each impact (N)
        real(dp), allocatable :: impact_moment_peak(:)  !! peak |M| of each impact (N m)
        real(dp) :: theta_max = 0.0_dp              !! largest |theta| (rad)
        real(dp) :: t_uplift = 0.0_dp               !! first partial contact (s), NaN none
        real(dp) :: t_lift_off = 0.0_dp             !! first complete loss of contact, NaN
        real(dp) :: t_touch_down = 0.0_dp           !! first contact after a complete loss
                                                    !! of contact (s), NaN none
        real(dp) :: t_overturn = 0.0_dp             !! last outward crossing of theta_overturn
                                                    !! before overturning, or the time
                                                    !! |theta| reached pi/2 when it was never
                                                    !! crossed (s); NaN
        real(dp) :: normal_max = 0.0_dp             !! largest N (N)
        real(dp) :: energy_error = 0.0_dp           !! largest |E + D - E_0 - W_in|/scale,
                                                    !! scale: the largest |E - E_rest|, |W_in|,
                                                    !! |D| of the run, E_rest = W (h - v_s/2)
        real(dp) :: t_end = 0.0_dp                  !! end of the run (s)
        integer :: n_steps = 0                      !! steps tried
        real(dp) :: t_safe = 0.0_dp                 !! time the energy criterion held (s), NaN
    end type winkler_run_t

    real(dp), parameter :: half_pi = 0.5_dp * pi, two_pi = 2.0_dp * pi
    real(dp), parameter :: rtol_default = 1.0e-9_dp, rtol_map_default = 1.0e-6_dp
    real(dp), parameter :: rtol_min = 1.0e-13_dp, rtol_max = 1.0e-3_dp
    integer, parameter :: max_steps_default = 2000000, steps_per_sample = 40
    integer, parameter :: max_steps_map = 200000
    !> Map runs go on after the pulse for map_free_p/p (s) at most.
    real(dp), parameter :: map_free_p = 100.0_dp
    !> The energy criterion keeps this fraction of the barrier in reserve for the
    !> non-conservative exchange of the projected-area pressure (doc/winkler.md (W.55)).
    real(dp), parameter :: barrier_margin = 0.05_dp
    !> A theta = 0 crossing is an impact only after a swing beyond impact_tol theta_c with an
    !> edge lifted (doc/winkler.md (W.49)): rocking at the kern level (an edge lifts once the
    !> resultant leaves the kern, at about a quarter of the rigid uplift acceleration) is not
    !> the rocking of the rigid model, and its amplitude vanishes as k grows.
    real(dp), parameter :: impact_tol = 1.0e-3_dp
    !> Smallest |sin theta| at which the Jacobian follows a delta = 0 end (1/sin theta).
    real(dp), parameter :: s_jac_min = 1.0e-100_dp
    !> Initial state: |v0| <= state_max r, |v_rate0| <= state_max r p, |theta_rate0| <=
    !> state_max p (no overflow in the energies).
    real(dp), parameter :: state_max = 1.0e6_dp
    integer, parameter :: NY = 6, NEV = 7, NSAMP = 4
    integer, parameter :: EV_EDGE_HI = 1, EV_EDGE_LO = 2, EV_Q_HI = 3, EV_Q_LO = 4, &
                          EV_THETA = 5, EV_OVERTURN = 6, EV_CAP = 7
    integer, parameter :: EV_TURN = 10        !! event i + EV_TURN: the rate of event i
    integer, parameter :: GR_NONE = 0, GR_PULSE = 1, GR_RECORD = 2
    integer, parameter :: WHY_REACHED = 0, WHY_OVERTURN = 1, WHY_LIMIT = 2, WHY_SAFE = 3, &
                          WHY_ERROR = 4
    integer, parameter :: END_EDGE = 0, END_DELTA = 1, END_Q = 2

    !> Ground acceleration on the current piece (m/s^2).
    type :: wr_ground_t
        integer :: src = GR_NONE
        type(pulse_t) :: p
        type(exp_consts_t) :: cexp
        real(dp) :: ta = 0.0_dp, tb = 0.0_dp, aa = 0.0_dp, ab = 0.0_dp, slope = 0.0_dp
    end type wr_ground_t

    !> The body on its foundation as a system of seispulse_ode (state: v, theta, v',
    !> theta', F, W_in).
    type, extends(ode_system) :: wr_ode_t
        real(dp) :: m = 1.0_dp, h = 1.0_dp, g = 9.80665_dp, j_g = 1.0_dp, i_o = 1.0_dp
        real(dp) :: r = 1.0_dp, alpha = 0.0_dp, k = 1.0_dp, c = 0.0_dp
        integer :: footing = FOOTING_CIRCLE, k_method = K_CONSTANT, reading = AXIS_LONG
        real(dp) :: theta_ov = 0.0_dp
        type(wr_ground_t) :: gr
        integer :: stat = SEISPULSE_SUCCESS
    contains
        procedure :: rhs => wr_rhs
        procedure :: event => wr_event
        procedure :: jacobian => wr_jacobian
    end type wr_ode_t

    !> One end of an interval of s, by its distances to the -r and +r edges (m).
    type :: end_t
        real(dp) :: d_lo = 0.0_dp, d_hi = 0.0_dp
        integer :: kind = END_EDGE
    end type end_t

    !> Contact forces at a state, with their derivatives in (v, theta, v', theta').
    type :: contact_t
        real(dp) :: width = 0.0_dp    !! geometric contact width b (m)
        real(dp) :: k_eff = 0.0_dp    !! Winkler modulus used (N/m^3)
        real(dp) :: n = 0.0_dp        !! N (N)
        real(dp) :: m = 0.0_dp        !! M (N m)
        real(dp) :: u = 0.0_dp        !! spring energy (J)
        real(dp) :: sn = 0.0_dp, cs = 1.0_dp   !! sin(theta), cos(theta) of the state
        real(dp) :: dn(4) = 0.0_dp, dm(4) = 0.0_dp
    end type contact_t

    !> N(v) - W at fixed theta, springs only (the settlement of the static branch).
    type, extends(scalar_function) :: settle_fn_t
        type(wr_ode_t) :: sys
        real(dp) :: theta = 0.0_dp
    contains
        procedure :: eval => settle_eval
    end type settle_fn_t

    !> State of a run.
    type :: wr_state_t
        type(wr_ode_t) :: sys
        type(ode_radau5_t) :: ode
        real(dp) :: t = 0.0_dp, y(NY) = 0.0_dp, f(NY) = 0.0_dp, h = 0.0_dp, h_max = 1.0_dp
        real(dp) :: p = 1.0_dp, t_lim = 0.0_dp
        real(dp) :: t_exc = 0.0_dp         !! end of the excitation (s)
        real(dp) :: rtol = 1.0e-9_dp, atol(NY) = 1.0_dp   !! step tolerances
        integer :: side(NEV) = 0
        logical :: active(NEV) = .false.
        logical :: lifted = .false.        !! an edge lifted since the last theta crossing
        real(dp) :: swing = 0.0_dp         !! largest |theta| since the last crossing (rad)
        real(dp) :: theta_imp = 0.0_dp     !! a swing must exceed it to end in an impact (rad)
        logical :: free = .false.          !! the excitation is over
        logical :: proof = .false.         !! constant k: the energy criterion applies
        logical :: safe = .false.          !! the energy criterion held
        logical :: map_mode = .false.      !! stop as soon as the class is known
        logical :: done = .false.
        real(dp) :: barrier = 0.0_dp, e_rest = 0.0_dp, e0 = 0.0_dp, u0 = 0.0_dp
        real(dp) :: e_scale = 0.0_dp, e_err = 0.0_dp
        real(dp) :: run_n = 0.0_dp, run_m = 0.0_dp
        integer :: open_imp = 0
        integer :: n_imp = 0, steps = 0, max_steps = max_steps_default
        integer :: ig = 1, ng = 0
        real(dp) :: t_out_cross = 0.0_dp
        real(dp), allocatable :: imp(:), pk_n(:), pk_m(:)
        real(dp), allocatable :: tg(:)
        integer :: stat = SEISPULSE_SUCCESS
        character(len=:), allocatable :: msg
    end type wr_state_t

    !> An event function on the dense output of the current step, for the root finder.
    type, extends(scalar_function) :: root_fn_t
        type(wr_state_t), pointer :: st => null()
        integer :: i = 0
        real(dp) :: hh = 0.0_dp
    contains
        procedure :: eval => root_eval
    end type root_fn_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> The model of `body` (cylinder_props: circle of radius body%r; block_props: rectangle
    !> of half-width body%r and half-length `alpha`, required) on Winkler soil of modulus k
    !> (N/m^3, finite, > 0), constant (default) or varying k (k_method, reading as
    !> varying_modulus; the given k is the full-contact value). Dashpots: c (N s/m^3, >= 0)
    !> given, or from the damping ratio xi (>= 0) of the small full-contact motion
    !> damping_ref (doc/winkler.md (W.42)): DAMP_ROCKING (default): c = 2 xi I_O omega_r/I,
    !> omega_r^2 = (k I - m g h)/I_O (needs k I > m g h); DAMP_VERTICAL: c = 2 xi sqrt(k m/A).
    !> Neither: c = 0. [AD11]'s own formula for omega_n is lost; these are the two
    !> natural readings. theta_overturn is the first zero of the imposed moment of
    !> seispulse_winkler's pushover of the same model (NaN if none).
    subroutine winkler_model(body, k, model, stat, errmsg, alpha, k_method, xi, damping_ref, c, &
                             reading)
        type(rocking_body_t), intent(in) :: body              !! the rigid body
        real(dp), intent(in) :: k                             !! Winkler modulus (N/m^3), > 0
        type(winkler_model_t), intent(out) :: model           !! the model
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> block half-length (m), > 0; required for a block, unused for a cylinder
        real(dp), intent(in), optional :: alpha
        !> K_CONSTANT or K_VARYING; default K_CONSTANT
        integer, intent(in), optional :: k_method
        !> damping ratio (-), >= 0; absent (and no c): no dashpots
        real(dp), intent(in), optional :: xi
        !> DAMP_ROCKING or DAMP_VERTICAL; default DAMP_ROCKING
        integer, intent(in), optional :: damping_ref
        !> dashpot (N s/m^3), >= 0; absent: from xi, or 0
        real(dp), intent(in), optional :: c
        !> AXIS_LONG or AXIS_SHORT (varying k); default AXIS_LONG
        integer, intent(in), optional :: reading
        type(winkler_pushover_t) :: res
        real(dp), allocatable :: th(:), curve(:, :)
        real(dp) :: w2, top
        integer :: ref, i
        integer, parameter :: n_push = 2001

        stat = SEISPULSE_SUCCESS
        call check_body(body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. in_open(k, 0.0_dp, 1.0e30_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'k = '//real_str(k) &
                           //': the Winkler modulus must be a finite number in (0, 1e30) (N/m^3)')
            return
        end if
        model%body = body
        model%r = body%r
        model%k = k
        if (body%shape == BODY_BLOCK) then
            if (.not. present(alpha)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha: the half-length' &
                               //' (m) of the block base is required for a block')
                return
            end if
            if (.not. in_open(alpha, 0.0_dp, 1.0e30_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'alpha = ' &
                               //real_str(alpha)//': must be a finite number in (0, 1e30) (m)')
                return
            end if
            model%footing = FOOTING_RECTANGLE
            model%alpha = alpha
            model%area = 4.0_dp * alpha * body%r                            ! (W.32)
            model%inertia = (4.0_dp / 3.0_dp) * alpha * body%r**3
        else
            model%footing = FOOTING_CIRCLE
            model%alpha = 0.0_dp
            model%area = pi * body%r**2
            model%inertia = 0.25_dp * pi * body%r**4
        end if
        model%v_static = body%weight / (k * model%area)
        model%k_method = K_CONSTANT
        if (present(k_method)) then
            if (k_method /= K_CONSTANT .and. k_method /= K_VARYING) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'k_method = ' &
                               //int_str(k_method)//': must be 1 (K_CONSTANT) or 2 (K_VARYING)')
                return
            end if
            model%k_method = k_method
        end if
        model%reading = AXIS_LONG
        if (present(reading)) then
            if (reading /= AXIS_LONG .and. reading /= AXIS_SHORT) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'reading = ' &
                               //int_str(reading)//': must be 1 (AXIS_LONG) or 2 (AXIS_SHORT)')
                return
            end if
            model%reading = reading
        end if
        if (present(c) .and. present(xi)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'c, xi: give the dashpot' &
                           //' constant or the damping ratio, not both')
            return
        end if
        model%c = 0.0_dp
        if (present(c)) then
            if (.not. in_closed(c, 0.0_dp, 1.0e30_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'c = '//real_str(c) &
                               //': the dashpot constant must be a finite number in [0, 1e30)' &
                               //' (N s/m^3)')
                return
            end if
            model%c = c
        else if (present(xi)) then
            if (.not. in_closed(xi, 0.0_dp, 100.0_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi = '//real_str(xi) &
                               //': the damping ratio must be a number in [0, 100]')
                return
            end if
            ref = DAMP_ROCKING
            if (present(damping_ref)) ref = damping_ref
            select case (ref)
            case (DAMP_ROCKING)
                ! (W.42): omega_r^2 = (k I - m g h)/I_O, c I = 2 xi I_O omega_r
                w2 = (k * model%inertia - body%weight * body%h) / (body%j_g + body%mass * body%h**2)
                if (.not. w2 > 0.0_dp) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'xi: k I = ' &
                                   //real_str(k * model%inertia)//' N m <= m g h = ' &
                                   //real_str(body%weight * body%h)//' N m: no rocking' &
                                   //' frequency on full contact; give c, or damping_ref =' &
                                   //' DAMP_VERTICAL')
                    return
                end if
                model%c = 2.0_dp * xi * (body%j_g + body%mass * body%h**2) * sqrt(w2) &
                          / model%inertia
            case (DAMP_VERTICAL)
                model%c = 2.0_dp * xi * sqrt(k * body%mass / model%area)      ! (W.43)
            case default
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'damping_ref = ' &
                               //int_str(ref)//': must be 1 (DAMP_ROCKING) or 2 (DAMP_VERTICAL)')
                return
            end select
        end if
        ! static overturning angle: the pushover of the same model (W.51)
        top = min(2.0_dp * body%theta_c, 0.5_dp * half_pi + 0.5_dp * body%theta_c)
        allocate(th(n_push), curve(n_push, 9))
        do i = 1, n_push
            th(i) = top * real(i - 1, dp) / real(n_push - 1, dp)
        end do
        if (model%footing == FOOTING_CIRCLE) then
            call winkler_pushover(body%r, body%h, body%weight, k, th, curve, res, stat, errmsg, &
                                  k_method=model%k_method, reading=model%reading)
        else
            call block_winkler_pushover(body%r, model%alpha, body%h, body%weight, k, th, curve, &
                                        res, stat, errmsg, k_method=model%k_method)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        model%theta_overturn = res%theta_overturn
    end subroutine winkler_model

    !> Rocking of `model` from (v0, theta0, v_rate0, theta_rate0) (default: at rest on its
    !> static settlement W/(k A), level) under a pulse of seispulse_pulses (m/s^2), or a
    !> record `accel` (units of g_rec m/s^2, default body%g; samples at t = (i - 1) dt,
    !> linear in between, 0 after the last), or free (neither).
    !> hist(:, j) holds the WR_OUT_* columns at t_grid(j) (finite, ascending; times <= 0
    !> give the initial state); after overturning theta = +-pi/2 and the other columns
    !> NaN, after a time limit all NaN. The run ends at overturning, or at t_max (default
    !> the last output time, or the end of the excitation without outputs; +inf: until the
    !> outcome is known or the step budget is spent), or once all outputs are written and
    !> the energy criterion says safe. Outcome: overturning classes by impacts; WR_RUN_SAFE
    !> when the energy criterion holds by the end (constant k, after the excitation: doc/winkler.md
    !> (W.55)); else WR_RUN_TIME_LIMIT. rtol: step tolerance (default 1e-9).
    subroutine winkler_rock(model, t_grid, hist, run, stat, errmsg, pulse, accel, dt, g_rec, &
                            v0, theta0, v_rate0, theta_rate0, t_max, rtol)
        type(winkler_model_t), intent(in) :: model            !! the model
        real(dp), intent(in) :: t_grid(:)                     !! output times (s), ascending
        real(dp), intent(out) :: hist(:, :)                   !! WR_NOUT x size(t_grid)
        type(winkler_run_t), intent(out) :: run               !! summary
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> ground acceleration (m/s^2); absent (and no record): free rocking
        type(pulse_t), intent(in), optional :: pulse
        !> record (units of g_rec); with dt, or absent
        real(dp), intent(in), optional :: accel(:)
        !> record step (s), > 0; required with accel
        real(dp), intent(in), optional :: dt
        !> unit of the record (m/s^2); default body%g
        real(dp), intent(in), optional :: g_rec
        !> initial settlement (m); default the static W/(k A)
        real(dp), intent(in), optional :: v0
        real(dp), intent(in), optional :: theta0              !! initial tilt (rad); default 0
        real(dp), intent(in), optional :: v_rate0             !! initial v' (m/s); default 0
        real(dp), intent(in), optional :: theta_rate0         !! initial theta' (rad/s); default 0
        !> end of the run (s), > 0 or +inf; default the last output time
        real(dp), intent(in), optional :: t_max
        real(dp), intent(in), optional :: rtol                !! step tolerance; default 1e-9
        type(wr_state_t) :: st
        type(piece_iter_t) :: it
        real(dp) :: y0(NY), rt, gu, t_exc
        real(dp), allocatable :: a_si(:)
        real(dp) :: no_record(0)

        call empty_run(run)
        hist = ieee_value(1.0_dp, ieee_quiet_nan)
        call check_model(model, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(hist, 1) /= WR_NOUT .or. size(hist, 2) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'hist: must be WR_NOUT x ' &
                           //'size(t_grid)')
            return
        end if
        call check_ascending_times(t_grid, 't_grid', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        y0 = 0.0_dp
        y0(1) = model%v_static
        if (present(v0)) y0(1) = v0
        if (present(theta0)) y0(2) = theta0
        if (present(v_rate0)) y0(3) = v_rate0
        if (present(theta_rate0)) y0(4) = theta_rate0
        if (.not. all(ieee_is_finite(y0))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'v0, theta0, v_rate0, ' &
                           //'theta_rate0: must be finite numbers (m, rad, m/s, rad/s)')
            return
        end if
        if (.not. (abs(y0(1)) <= state_max * model%r .and. &
                   abs(y0(3)) <= state_max * model%r * model%body%p .and. &
                   abs(y0(4)) <= state_max * model%body%p)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'v0, v_rate0, theta_rate0: ' &
                           //'|v0| <= 1e6 r (m), |v_rate0| <= 1e6 r p (m/s), |theta_rate0| ' &
                           //'<= 1e6 p (rad/s), p of the rigid body')
            return
        end if
        if (.not. abs(y0(2)) < half_pi) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'theta0 = '//real_str(y0(2)) &
                           //': must be in (-pi/2, pi/2) (rad)')
            return
        end if
        call check_rtol(rtol, rtol_default, rt, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(pulse) .and. present(accel)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pulse, accel: give a ' &
                           //'pulse or a record, not both')
            return
        end if
        if (present(t_max)) then
            if (outside(t_max, 0.0_dp, ieee_value(1.0_dp, ieee_positive_inf), .true., &
                        .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_max = ' &
                               //real_str(t_max)//': must be a number > 0 (s) or +inf')
                return
            end if
        end if
        call setup(st, model, rt)
        t_exc = 0.0_dp
        if (present(pulse)) then
            call pulse_validate(pulse, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call pulse_pieces_check(pulse, 'winkler_rock', stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            st%sys%gr%src = GR_PULSE
            st%sys%gr%p = pulse
            if (pulse%kind == PULSE_EXPONENTIAL) st%sys%gr%cexp = exp_consts(pulse%beta)
            call pulse_pieces_init(it, pulse)
            t_exc = excitation_end(pulse)
        else if (present(accel)) then
            if (.not. present(dt)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt: the sampling ' &
                               //'step (> 0, s) of the record is required')
                return
            end if
            gu = model%body%g
            if (present(g_rec)) gu = g_rec
            call record_step_check(accel, dt, gu, stat, errmsg, name='accel')
            if (stat /= SEISPULSE_SUCCESS) return
            call record_in_si(accel, gu, a_si, stat, errmsg, name='accel')
            if (stat /= SEISPULSE_SUCCESS) return
            if (real(steps_per_sample, dp) * size(accel) &
                    < real(huge(1) - max_steps_default, dp)) &
                st%max_steps = max_steps_default + steps_per_sample * size(accel)
            st%sys%gr%src = GR_RECORD
            call record_pieces_init(it, size(accel), dt)
            t_exc = dt * real(size(accel) - 1, dp)
        end if
        st%t_exc = t_exc
        st%t_lim = t_exc
        if (size(t_grid) > 0) st%t_lim = max(t_grid(size(t_grid)), 0.0_dp)
        ! free motion with neither outputs nor t_max: until the outcome is known
        if (size(t_grid) == 0 .and. .not. t_exc > 0.0_dp) st%t_lim = huge(1.0_dp)
        if (present(t_max)) st%t_lim = min(t_max, huge(1.0_dp))
        if (allocated(a_si)) then
            call simulate(st, it, a_si, y0, t_grid, hist, run, stat, errmsg)
        else
            call simulate(st, it, no_record, y0, t_grid, hist, run, stat, errmsg)
        end if
    end subroutine winkler_rock

    !> Overturning map of the model under a pulse family: classes(i, j) for the amplitude
    !> y(i) and frequency x(j): 0 safe, 1 overturns without impact, 2 after one impact,
    !> 3 after more, -1 undecided (time or step budget), as on rigid ground. Axes as
    !> seispulse_cylinder's body_overturning_map, with the rigid p and theta_c of
    !> model%body: MAP_AXES_DIMENSIONLESS: x = omega_p/p, y = a_p/(g tan theta_c);
    !> MAP_AXES_DIMENSIONAL: x = f_p (Hz), y = PGA (g). omega_p = 2 pi/T_p of the pulse
    !> duration, or 2 pi f_p of the Ricker wavelet (its dominant frequency; t0 from
    !> template%t0 * template%freq, default 1.5/f_p). Each cell starts at rest and runs
    !> to the end of the pulse and on for at most 100/p (s): overturned, safe (by the energy
    !> criterion, constant k, or standing at the end of that window), or -1 when the step
    !> budget runs out first. rtol: default 1e-6 (doc/winkler.md (W.58)).
    subroutine winkler_overturning_map(model, kind, x, y, axes, classes, stat, errmsg, &
                                       template, rtol)
        type(winkler_model_t), intent(in) :: model            !! the model
        integer, intent(in) :: kind                           !! PULSE_* code (not PULSE_MP)
        real(dp), intent(in) :: x(:)                          !! frequencies (axes), > 0
        real(dp), intent(in) :: y(:)                          !! amplitudes (axes), >= 0
        integer, intent(in) :: axes                           !! MAP_AXES_* code
        integer, intent(out) :: classes(:, :)                 !! size(y) x size(x)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> shape parameters of the kind; absent: pulse_t defaults
        type(pulse_t), intent(in), optional :: template
        real(dp), intent(in), optional :: rtol                !! step tolerance; default 1e-6
        type(wr_state_t) :: st
        type(piece_iter_t) :: it
        type(pulse_t) :: pl
        type(winkler_run_t) :: run
        real(dp) :: rt, tan_c, t0f, om, y0(NY), no_record(0), hist(WR_NOUT, 0), no_grid(0)
        integer :: i, j

        classes = -1
        call check_model(model, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        select case (kind)
        case (PULSE_EXPONENTIAL, PULSE_HALF_SINE, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, &
              PULSE_RECTANGULAR, PULSE_TRIANGULAR, PULSE_RICKER)
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'kind = '//int_str(kind) &
                           //' ('//pulse_kind_name(kind)//'): maps take an acceleration' &
                           //' pulse with a time scale: exponential, half_sine, sine_cycle,' &
                           //' cosine_cycle, rectangular, triangular or ricker')
            return
        end select
        if (axes /= MAP_AXES_DIMENSIONLESS .and. axes /= MAP_AXES_DIMENSIONAL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'axes = '//int_str(axes) &
                           //': must be 1 (MAP_AXES_DIMENSIONLESS) or 2 (MAP_AXES_DIMENSIONAL)')
            return
        end if
        if (size(classes, 1) /= size(y) .or. size(classes, 2) /= size(x)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'classes: must be ' &
                           //'size(y) x size(x)')
            return
        end if
        do j = 1, size(x)
            if (.not. in_open(x(j), 0.0_dp, 1.0e30_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x('//int_str(j)//') = ' &
                               //real_str(x(j))//': must be a finite number in (0, 1e30)')
                return
            end if
        end do
        do i = 1, size(y)
            if (.not. in_closed(y(i), 0.0_dp, 1.0e30_dp)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'y('//int_str(i)//') = ' &
                               //real_str(y(i))//': must be a finite number in [0, 1e30)')
                return
            end if
        end do
        call check_rtol(rtol, rtol_map_default, rt, stat, errmsg)
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
        tan_c = tan(model%body%theta_c)
        y0 = 0.0_dp
        y0(1) = model%v_static
        call setup(st, model, rt)
        st%map_mode = .true.
        do j = 1, size(x)
            if (axes == MAP_AXES_DIMENSIONAL) then
                om = two_pi * x(j)
            else
                om = x(j) * model%body%p
            end if
            if (kind == PULSE_RICKER) then
                pl%freq = om / two_pi
                pl%t0 = t0f / pl%freq
            else
                pl%duration = two_pi / om
            end if
            do i = 1, size(y)
                if (axes == MAP_AXES_DIMENSIONAL) then
                    pl%amp = y(i) * model%body%g
                else
                    pl%amp = y(i) * model%body%g * tan_c
                end if
                if (i == 1) then
                    call pulse_validate(pl, stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                    call pulse_pieces_check(pl, 'winkler_overturning_map', stat, errmsg)
                    if (stat /= SEISPULSE_SUCCESS) return
                end if
                st%sys%gr%src = GR_PULSE
                st%sys%gr%p = pl
                if (kind == PULSE_EXPONENTIAL) st%sys%gr%cexp = exp_consts(pl%beta)
                call pulse_pieces_init(it, pl)
                st%t_exc = excitation_end(pl)
                st%t_lim = st%t_exc + map_free_p / model%body%p
                st%max_steps = max_steps_map
                call simulate(st, it, no_record, y0, no_grid, hist, run, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                select case (run%outcome)
                case (WR_RUN_SAFE, WR_RUN_OVERTURN_NO_IMPACT, WR_RUN_OVERTURN_ONE_IMPACT, &
                      WR_RUN_OVERTURN_IMPACTS)
                    classes(i, j) = run%outcome
                case (WR_RUN_TIME_LIMIT)
                    ! standing at the end of the window (no energy criterion: varying k, or
                    ! energy still above it): safe within the window; -1 only when the step
                    ! budget ran out first
                    classes(i, j) = -1
                    if (run%t_end >= st%t_lim) classes(i, j) = WR_RUN_SAFE
                case default
                    classes(i, j) = -1
                end select
            end do
        end do
    end subroutine winkler_overturning_map

    !> Name of a run outcome (WR_RUN_*), '' for another code.
    pure function winkler_outcome_name(code) result(name)
        integer, intent(in) :: code  !! WR_RUN_* code
        character(len=len_trim(winkler_outcome_name_text(code))) :: name
        name = winkler_outcome_name_text(code)
    end function winkler_outcome_name

    !> winkler_outcome_name(code) padded with blanks.
    pure function winkler_outcome_name_text(code) result(name)
        integer, intent(in) :: code
        character(len=64) :: name
        select case (code)
        case (WR_RUN_SAFE)
            name = 'safe'
        case (WR_RUN_OVERTURN_NO_IMPACT)
            name = 'overturn_no_impact'
        case (WR_RUN_OVERTURN_ONE_IMPACT)
            name = 'overturn_one_impact'
        case (WR_RUN_OVERTURN_IMPACTS)
            name = 'overturn_many_impacts'
        case (WR_RUN_TIME_LIMIT)
            name = 'time_limit'
        case default
            name = ''
        end select
    end function winkler_outcome_name_text

    !> Name of an output column (WR_OUT_*), '' for another index.
    pure function winkler_output_name(k) result(name)
        integer, intent(in) :: k  !! column index
        character(len=len_trim(winkler_output_name_text(k))) :: name
        name = winkler_output_name_text(k)
    end function winkler_output_name

    !> winkler_output_name(k) padded with blanks.
    pure function winkler_output_name_text(k) result(name)
        integer, intent(in) :: k
        character(len=64) :: name
        select case (k)
        case (WR_OUT_V)
            name = 'v'
        case (WR_OUT_THETA)
            name = 'theta'
        case (WR_OUT_V_RATE)
            name = 'v_rate'
        case (WR_OUT_THETA_RATE)
            name = 'theta_rate'
        case (WR_OUT_WIDTH)
            name = 'contact_width'
        case (WR_OUT_NORMAL)
            name = 'normal_force'
        case (WR_OUT_MOMENT)
            name = 'moment'
        case (WR_OUT_ACCEL)
            name = 'ground_accel'
        case (WR_OUT_ENERGY)
            name = 'energy'
        case (WR_OUT_WORK)
            name = 'input_work'
        case (WR_OUT_DISSIPATED)
            name = 'dissipated'
        case default
            name = ''
        end select
    end function winkler_output_name_text

    !> Contact width b (m), Winkler modulus used (N/m^3), N (N), M (N m) and spring energy
    !> U (J) of `model` at the state (v, theta, v', theta') (m, rad, m/s, rad/s), with the
    !> derivatives dn, dm of N and M in (v, theta, v', theta') (W.33)-(W.35), (W.44).
    subroutine winkler_contact_forces(model, state, width, k_eff, n, m, u, dn, dm)
        type(winkler_model_t), intent(in) :: model  !! the model
        real(dp), intent(in) :: state(4)            !! v, theta, v', theta'
        real(dp), intent(out) :: width  !! contact width b (m)
        real(dp), intent(out) :: k_eff  !! Winkler modulus used (N/m^3)
        real(dp), intent(out) :: n      !! normal force N (N)
        real(dp), intent(out) :: m      !! moment M (N m)
        real(dp), intent(out) :: u      !! spring energy U (J)
        !> dN/d(v, theta, v', theta') (N/m, N/rad, N s/m, N s/rad)
        real(dp), intent(out), optional :: dn(4)
        !> dM/d(v, theta, v', theta') (N, N m/rad, N s, N m s/rad)
        real(dp), intent(out), optional :: dm(4)
        type(wr_ode_t) :: sys
        type(contact_t) :: ct
        call load_model(sys, model)
        call contact(sys, state, ct, present(dn) .or. present(dm))
        width = ct%width
        k_eff = ct%k_eff
        n = ct%n
        m = ct%m
        u = ct%u
        if (present(dn)) dn = ct%dn
        if (present(dm)) dm = ct%dm
    end subroutine winkler_contact_forces

    !> The right-hand side f (NY = 6: v', theta', v'', theta'', F', W_in') and its exact
    !> Jacobian (6 x 6) at the state y (v, theta, v', theta', F, W_in) under the ground
    !> acceleration a_g (m/s^2) (W.36)-(W.47): for checks and tests.
    subroutine winkler_rhs_jacobian(model, a_g, y, f, dfdy)
        type(winkler_model_t), intent(in) :: model  !! the model
        real(dp), intent(in) :: a_g                 !! ground acceleration (m/s^2)
        real(dp), intent(in) :: y(NY)               !! state
        real(dp), intent(out) :: f(NY)              !! derivative
        real(dp), intent(out) :: dfdy(NY, NY)       !! Jacobian
        type(wr_ode_t) :: sys
        call load_model(sys, model)
        sys%gr%src = GR_RECORD
        sys%gr%aa = a_g
        sys%gr%ab = a_g
        sys%gr%tb = huge(1.0_dp)
        call sys%rhs(0.0_dp, y, f)
        call sys%jacobian(0.0_dp, y, f, dfdy)
    end subroutine winkler_rhs_jacobian

    !> The mountain-pass barrier of a constant-k model (J): U_min(theta_overturn) -
    !> U_min(0), U_min(theta) = min over v of m g z_G + U (W.54), and the settlement v
    !> (m) of that minimum at theta_overturn; NaN if the model has no overturning angle.
    subroutine winkler_barrier(model, barrier, v_ov, stat, errmsg)
        type(winkler_model_t), intent(in) :: model            !! the model
        real(dp), intent(out) :: barrier                      !! (J)
        real(dp), intent(out) :: v_ov                         !! (m)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(wr_ode_t) :: sys
        call load_model(sys, model)
        call barrier_of(sys, model%v_static, barrier, v_ov, stat, errmsg)
    end subroutine winkler_barrier

    ! ------------------------------------------------------------------------------
    ! Set-up and checks
    ! ------------------------------------------------------------------------------

    subroutine check_body(body, stat, errmsg)
        type(rocking_body_t), intent(in) :: body
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. (finite_positive(body%r) .and. finite_positive(body%h) .and. &
                   finite_positive(body%mass) .and. finite_positive(body%g) .and. &
                   finite_positive(body%j_g) .and. finite_positive(body%p) .and. &
                   finite_positive(body%weight) .and. finite_positive(body%theta_c))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'body: r, h, mass, g, j_g,' &
                           //' p, weight and theta_c must be finite numbers > 0 (build the' &
                           //' body with cylinder_props or block_props)')
        end if
    end subroutine check_body

    subroutine check_model(model, stat, errmsg)
        type(winkler_model_t), intent(in) :: model
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call check_body(model%body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (model%footing == FOOTING_CIRCLE .or. model%footing == FOOTING_RECTANGLE) &
            .or. .not. finite_positive(model%r) .or. .not. finite_positive(model%k) &
            .or. .not. finite_at_least(model%c, 0.0_dp) .or. .not. finite_positive(model%area) &
            .or. .not. finite_positive(model%v_static) &
            .or. .not. (model%k_method == K_CONSTANT .or. model%k_method == K_VARYING)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model: footing, r, k, c,' &
                           //' k_method out of range (build the model with winkler_model)')
            return
        end if
        if (model%footing == FOOTING_RECTANGLE .and. .not. finite_positive(model%alpha)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model%alpha = ' &
                           //real_str(model%alpha)//': the half-length must be > 0 (m)')
            return
        end if
        if (model%reading /= AXIS_LONG .and. model%reading /= AXIS_SHORT) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model%reading = ' &
                           //int_str(model%reading)//': must be 1 (AXIS_LONG) or 2 (AXIS_SHORT)')
            return
        end if
        ! the derived fields (v_static, theta_overturn) belong to k: a model edited after
        ! winkler_model would keep a stale overturning angle
        if (.not. abs(model%v_static * model%k * model%area / model%body%weight - 1.0_dp) &
                <= 1.0e-12_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'model: k, area or the ' &
                           //'weight changed after winkler_model (build the model again)')
        end if
    end subroutine check_model

    !> The step tolerance: rtol if given (in [1e-13, 1e-3]), else the default.
    subroutine check_rtol(rtol, default, rt, stat, errmsg)
        real(dp), intent(in), optional :: rtol
        real(dp), intent(in) :: default
        real(dp), intent(out) :: rt
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        rt = default
        if (present(rtol)) rt = rtol
        if (.not. in_closed(rt, rtol_min, rtol_max)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'rtol = '//real_str(rt) &
                           //': must be in [1e-13, 1e-3]')
        end if
    end subroutine check_rtol

    !> The system's parameters from a (valid) model.
    pure subroutine load_model(sys, model)
        type(wr_ode_t), intent(inout) :: sys
        type(winkler_model_t), intent(in) :: model
        sys%m = model%body%mass
        sys%h = model%body%h
        sys%g = model%body%g
        sys%j_g = model%body%j_g
        sys%i_o = model%body%j_g + model%body%mass * model%body%h**2
        sys%r = model%r
        sys%alpha = model%alpha
        sys%k = model%k
        sys%c = model%c
        sys%footing = model%footing
        sys%k_method = model%k_method
        sys%reading = model%reading
        sys%theta_ov = model%theta_overturn
    end subroutine load_model

    !> Settings of a run (tolerances, scales, barrier), the same for every cell of a map.
    subroutine setup(st, model, rtol)
        type(wr_state_t), intent(inout) :: st
        type(winkler_model_t), intent(in) :: model
        real(dp), intent(in) :: rtol
        real(dp) :: vs, ths, wv, v_ov
        integer :: stat
        call load_model(st%sys, model)
        st%p = model%body%p
        st%theta_imp = impact_tol * model%body%theta_c
        vs = model%v_static
        ths = vs / model%r
        wv = sqrt(model%k * model%area / model%body%mass)
        st%h_max = 0.5_dp / st%p
        st%rtol = rtol
        st%atol = rtol * [vs, ths, vs * wv, ths * wv, model%body%weight * vs, &
                          model%body%weight * vs]
        st%e_rest = model%body%weight * (model%body%h - 0.5_dp * vs)
        st%proof = model%k_method == K_CONSTANT .and. ieee_is_finite(model%theta_overturn)
        st%barrier = ieee_value(1.0_dp, ieee_quiet_nan)
        if (st%proof) then
            call barrier_of(st%sys, vs, st%barrier, v_ov, stat)
            st%proof = stat == SEISPULSE_SUCCESS .and. st%barrier > 0.0_dp
        end if
    end subroutine setup

    subroutine empty_run(run)
        type(winkler_run_t), intent(inout) :: run
        real(dp) :: nan
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        if (allocated(run%t_impacts)) deallocate(run%t_impacts)
        if (allocated(run%impact_normal_peak)) deallocate(run%impact_normal_peak)
        if (allocated(run%impact_moment_peak)) deallocate(run%impact_moment_peak)
        allocate(run%t_impacts(0), run%impact_normal_peak(0), run%impact_moment_peak(0))
        run%outcome = WR_RUN_TIME_LIMIT
        run%n_impacts = 0
        run%theta_max = 0.0_dp
        run%t_uplift = nan
        run%t_lift_off = nan
        run%t_touch_down = nan
        run%t_overturn = nan
        run%t_safe = nan
        run%normal_max = 0.0_dp
        run%energy_error = 0.0_dp
        run%t_end = 0.0_dp
        run%n_steps = 0
    end subroutine empty_run

    !> Barrier (W.54) of the system with its static settlement vs (m).
    subroutine barrier_of(sys, vs, barrier, v_ov, stat, errmsg)
        type(wr_ode_t), intent(in) :: sys
        real(dp), intent(in) :: vs
        real(dp), intent(out) :: barrier, v_ov
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(settle_fn_t) :: fn
        type(contact_t) :: ct
        real(dp) :: s, c, area, lo, hi, u0
        barrier = ieee_value(1.0_dp, ieee_quiet_nan)
        v_ov = barrier
        stat = SEISPULSE_SUCCESS
        if (.not. ieee_is_finite(sys%theta_ov)) return
        fn%sys = sys
        fn%sys%c = 0.0_dp
        fn%sys%k_method = K_CONSTANT
        fn%theta = sys%theta_ov
        s = sin(sys%theta_ov)
        c = cos(sys%theta_ov)
        ! N(v) = 0 at v = -r |s| (no contact); N >= k c A (v - r |s|) >= W at the top
        area = pi * sys%r**2
        if (sys%footing == FOOTING_RECTANGLE) area = 4.0_dp * sys%alpha * sys%r
        lo = -sys%r * abs(s)
        hi = sys%r * abs(s) + sys%m * sys%g / (sys%k * area * c)
        call find_root(fn, lo, hi, v_ov, stat, errmsg, fa_known=-sys%m * sys%g)
        if (stat /= SEISPULSE_SUCCESS) return
        call contact(fn%sys, [v_ov, sys%theta_ov, 0.0_dp, 0.0_dp], ct, .false.)
        ! U_min(0): full contact at the static settlement, W vs/2 of spring energy
        u0 = sys%m * sys%g * (sys%h - 0.5_dp * vs)
        barrier = sys%m * sys%g * (sys%h * c - v_ov) + ct%u - u0               ! (W.54)
    end subroutine barrier_of

    function settle_eval(self, x) result(y)
        class(settle_fn_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        type(contact_t) :: ct
        call contact(self%sys, [x, self%theta, 0.0_dp, 0.0_dp], ct, .false.)
        y = ct%n - self%sys%m * self%sys%g
    end function settle_eval

    ! ------------------------------------------------------------------------------
    ! Contact (doc/winkler.md (W.30)-(W.35), (W.44))
    ! ------------------------------------------------------------------------------

    !> Restrict [lo, hi] to where the linear form f(s) > 0, given its values at the edges
    !> f_lo = f(-r), f_hi = f(+r); the root's edge distances come from those values
    !> (2 r f_lo/(f_lo - f_hi): a sum of magnitudes in the denominator) (W.33).
    pure subroutine restrict(f_lo, f_hi, two_r, kind, lo, hi, empty)
        real(dp), intent(in) :: f_lo, f_hi, two_r
        integer, intent(in) :: kind
        type(end_t), intent(inout) :: lo, hi
        logical, intent(inout) :: empty
        real(dp) :: den
        type(end_t) :: e
        if (empty) return
        if (f_lo > 0.0_dp .and. f_hi > 0.0_dp) return
        if (.not. (f_lo > 0.0_dp .or. f_hi > 0.0_dp)) then
            empty = .true.
            return
        end if
        e%kind = kind
        if (f_lo > 0.0_dp) then
            ! f > 0 below the root: an upper end
            den = f_lo - f_hi
            e%d_lo = two_r * (f_lo / den)
            e%d_hi = two_r * (-f_hi / den)
            if (e%d_lo < hi%d_lo) hi = e
        else
            den = f_hi - f_lo
            e%d_lo = two_r * (-f_lo / den)
            e%d_hi = two_r * (f_hi / den)
            if (e%d_lo > lo%d_lo) lo = e
        end if
        if (.not. lo%d_lo < hi%d_lo) empty = .true.
    end subroutine restrict

    !> s (m) of an end, from the nearer edge.
    elemental function end_s(e, r) result(s)
        type(end_t), intent(in) :: e
        real(dp), intent(in) :: r
        real(dp) :: s
        if (e%d_lo <= e%d_hi) then
            s = e%d_lo - r
        else
            s = r - e%d_hi
        end if
    end function end_s

    !> Full width 2 w(s) (m) of the base at an end.
    elemental function end_width(e, footing, alpha) result(w2)
        type(end_t), intent(in) :: e
        integer, intent(in) :: footing
        real(dp), intent(in) :: alpha
        real(dp) :: w2
        if (footing == FOOTING_CIRCLE) then
            w2 = 2.0_dp * sqrt(max(e%d_lo, 0.0_dp) * max(e%d_hi, 0.0_dp))
        else
            w2 = 2.0_dp * alpha
        end if
    end function end_width

    !> Contact forces at y (v, theta, v', theta'): width, k, N, M, U and, with `deriv`,
    !> the derivatives of N and M (W.44). With no_u = .true., U is left 0 (the right-hand
    !> side and the Jacobian do not need it): the moments of the geometric interval are
    !> then skipped where the active one differs (a dashpot end during uplift).
    subroutine contact(sys, y, ct, deriv, no_u)
        class(wr_ode_t), intent(inout) :: sys
        real(dp), intent(in) :: y(:)
        type(contact_t), intent(out) :: ct
        logical, intent(in) :: deriv
        logical, intent(in), optional :: no_u
        type(end_t) :: glo, ghi, alo, ahi
        real(dp) :: s, c, v, vd, thd, dl, dh, ql, qh, two_r, aq, bq, m(0:2), gm(0:2), kb, &
                    dkb, kk, bd(4), ky(4), ay(4), by(4), sa, sb, wa, wb, qa, qb, dsa(4), dsb(4)
        logical :: gempty, aempty, alo_d, ahi_d, same_ends, want_u
        integer :: stat
        want_u = .true.
        if (present(no_u)) want_u = .not. no_u
        v = y(1)
        s = sin(y(2))
        c = cos(y(2))
        ct%sn = s
        ct%cs = c
        vd = y(3)
        thd = y(4)
        two_r = 2.0_dp * sys%r
        dl = v + sys%r * s                                                   ! (W.30)
        dh = v - sys%r * s
        glo = end_t(0.0_dp, two_r, END_EDGE)
        ghi = end_t(two_r, 0.0_dp, END_EDGE)
        gempty = .false.
        call restrict(dl, dh, two_r, END_DELTA, glo, ghi, gempty)
        ct%dn = 0.0_dp
        ct%dm = 0.0_dp
        ct%k_eff = sys%k
        if (gempty) return
        ! geometric width: one of the ends is an edge (W.35)
        if (glo%kind == END_EDGE) then
            ct%width = ghi%d_lo
        else
            ct%width = glo%d_hi
        end if
        kb = sys%k
        dkb = 0.0_dp
        if (sys%k_method == K_VARYING) then
            call varying_modulus(sys%footing, sys%r, sys%alpha, sys%k, ct%width, kb, stat, &
                                 reading=sys%reading)
            if (stat /= SEISPULSE_SUCCESS) sys%stat = stat
            if (deriv) dkb = modulus_slope(sys, ct%width, kb)
        end if
        ct%k_eff = kb
        ql = kb * dl + sys%c * (vd + sys%r * c * thd)
        qh = kb * dh + sys%c * (vd - sys%r * c * thd)
        alo = glo
        ahi = ghi
        aempty = .false.
        if (sys%c > 0.0_dp) call restrict(ql, qh, two_r, END_Q, alo, ahi, aempty)
        same_ends = alo%kind == glo%kind .and. ahi%kind == ghi%kind
        if (want_u .or. (same_ends .and. .not. aempty)) then
            call strip_moments(sys%footing, sys%r, sys%alpha, glo%d_lo, glo%d_hi, ghi%d_lo, &
                               ghi%d_hi, gm)
            if (want_u) ct%u = 0.5_dp * kb * c * ((v * v) * gm(0) - (2.0_dp * v * s) * gm(1) &
                                                  + (s * s) * gm(2))
        end if
        if (aempty) return
        if (same_ends) then
            m = gm
        else
            call strip_moments(sys%footing, sys%r, sys%alpha, alo%d_lo, alo%d_hi, ahi%d_lo, &
                               ahi%d_hi, m)
        end if
        aq = kb * v + sys%c * vd                                             ! (W.34)
        bq = kb * s + sys%c * c * thd
        ct%n = c * (aq * m(0) - bq * m(1))
        ct%m = c * c * (aq * m(1) - bq * m(2))
        if (.not. deriv) return
        ! (W.44): d/dy of the integrals; the ends move only where delta = 0 (a q = 0 end has
        ! a zero integrand, an edge is fixed)
        dsa = 0.0_dp
        dsb = 0.0_dp
        sa = end_s(alo, sys%r)
        sb = end_s(ahi, sys%r)
        ! a delta = 0 end inside the base needs |v| <= r |sin theta|: below |s| = 1e-100 (a
        ! grazing start, theta0 ~ 0 and v0 ~ 0) its motion is left out of the Jacobian
        ! (only Newton's rate depends on it), so that no 1/s overflows
        if (.not. abs(s) >= s_jac_min) then
            alo_d = .false.
            ahi_d = .false.
        else
            alo_d = alo%kind == END_DELTA
            ahi_d = ahi%kind == END_DELTA
        end if
        if (alo_d) dsa = [1.0_dp, -sa * c, 0.0_dp, 0.0_dp] / s
        if (ahi_d) dsb = [1.0_dp, -sb * c, 0.0_dp, 0.0_dp] / s
        ky = 0.0_dp
        if (sys%k_method == K_VARYING) then
            ! b = s_hi + r (contact on the -r side) or r - s_lo, from the geometric ends
            bd = 0.0_dp
            if (ghi%kind == END_DELTA .and. abs(s) >= s_jac_min) then
                bd = [1.0_dp, -end_s(ghi, sys%r) * c, 0.0_dp, 0.0_dp] / s
            else if (glo%kind == END_DELTA .and. abs(s) >= s_jac_min) then
                bd = -[1.0_dp, -end_s(glo, sys%r) * c, 0.0_dp, 0.0_dp] / s
            end if
            ky = dkb * bd
        end if
        kk = kb
        ay = [kk, 0.0_dp, sys%c, 0.0_dp] + v * ky
        by = [0.0_dp, kk * c - sys%c * s * thd, 0.0_dp, sys%c * c] + s * ky
        ct%dn = c * (ay * m(0) - by * m(1))
        ct%dm = c * c * (ay * m(1) - by * m(2))
        ct%dn(2) = ct%dn(2) - s * (aq * m(0) - bq * m(1))
        ct%dm(2) = ct%dm(2) - 2.0_dp * c * s * (aq * m(1) - bq * m(2))
        if (alo%kind == END_DELTA) then
            qa = sys%c * (vd - sa * c * thd)
            wa = end_width(alo, sys%footing, sys%alpha)
            ct%dn = ct%dn - c * qa * wa * dsa
            ct%dm = ct%dm - c * c * qa * sa * wa * dsa
        end if
        if (ahi%kind == END_DELTA) then
            qb = sys%c * (vd - sb * c * thd)
            wb = end_width(ahi, sys%footing, sys%alpha)
            ct%dn = ct%dn + c * qb * wb * dsb
            ct%dm = ct%dm + c * c * qb * sb * wb * dsb
        end if
    end subroutine contact

    !> dk/db of the varying modulus at the width b (N/m^4): a central difference of
    !> varying_modulus (smooth in b; the one derivative of the Jacobian that is not in
    !> closed form), one-sided at full contact.
    function modulus_slope(sys, b, kb) result(dk)
        class(wr_ode_t), intent(inout) :: sys
        real(dp), intent(in) :: b, kb
        real(dp) :: dk
        real(dp) :: db, k1, k2, bm, bp
        integer :: stat
        db = 1.0e-6_dp * b
        bp = min(b + db, 2.0_dp * sys%r)
        bm = b - db
        call varying_modulus(sys%footing, sys%r, sys%alpha, sys%k, bp, k2, stat, &
                             reading=sys%reading)
        call varying_modulus(sys%footing, sys%r, sys%alpha, sys%k, bm, k1, stat, &
                             reading=sys%reading)
        dk = (k2 - k1) / (bp - bm)
        if (.not. ieee_is_finite(dk)) dk = 0.0_dp
        if (kb < 0.0_dp) dk = 0.0_dp
    end function modulus_slope

    ! ------------------------------------------------------------------------------
    ! Equations of motion (doc/winkler.md (W.36)-(W.47))
    ! ------------------------------------------------------------------------------

    !> Ground acceleration (m/s^2) at t on the current piece (the limit from inside at
    !> its end).
    pure function ground_accel(gr, t) result(a)
        type(wr_ground_t), intent(in) :: gr
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
            if (t >= gr%tb) then
                a = gr%ab
            else
                a = gr%aa + gr%slope * (t - gr%ta)
            end if
        case default
            a = 0.0_dp
        end select
    end function ground_accel

    !> Accelerations (W.38) from the contact forces.
    pure subroutine accelerations(sys, s, c, thd, a, n, m, vdd, thdd, det, b1, b2)
        type(wr_ode_t), intent(in) :: sys
        real(dp), intent(in) :: s, c, thd, a, n, m
        real(dp), intent(out) :: vdd, thdd, det, b1, b2
        b1 = sys%m * sys%g - n - sys%m * sys%h * c * thd * thd
        b2 = sys%m * sys%g * sys%h * s + m + sys%m * a * sys%h * c
        det = sys%m * sys%j_g + (sys%m * sys%h * c)**2
        vdd = (sys%i_o * b1 - sys%m * sys%h * s * b2) / det
        thdd = (sys%m * b2 - sys%m * sys%h * s * b1) / det
    end subroutine accelerations

    subroutine wr_rhs(self, t, y, dydt)
        class(wr_ode_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        type(contact_t) :: ct
        real(dp) :: a, s, c, vdd, thdd, det, b1, b2, d(NY)
        call contact(self, y, ct, .false., no_u=.true.)
        a = ground_accel(self%gr, t)
        s = ct%sn
        c = ct%cs
        call accelerations(self, s, c, y(4), a, ct%n, ct%m, vdd, thdd, det, b1, b2)
        d = [y(3), y(4), vdd, thdd, ct%n * y(3) - ct%m * y(4), &             ! (W.40)
             self%m * a * self%h * c * y(4)]
        dydt(1:NY) = d
    end subroutine wr_rhs

    !> The exact Jacobian (W.45)-(W.47).
    subroutine wr_jacobian(self, t, y, f, dfdy)
        class(wr_ode_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(in) :: f(:)
        real(dp), contiguous, intent(out) :: dfdy(:, :)
        type(contact_t) :: ct
        real(dp) :: a, s, c, thd, vdd, thdd, det, b1, b2, b1y(4), b2y(4), py(4), qy(4), dety(4), &
                    mh
        associate(unused => f)
        end associate
        call contact(self, y, ct, .true., no_u=.true.)
        a = ground_accel(self%gr, t)
        s = ct%sn
        c = ct%cs
        thd = y(4)
        mh = self%m * self%h
        call accelerations(self, s, c, thd, a, ct%n, ct%m, vdd, thdd, det, b1, b2)
        b1y = -ct%dn
        b1y(2) = b1y(2) + mh * s * thd * thd
        b1y(4) = b1y(4) - 2.0_dp * mh * c * thd
        b2y = ct%dm
        b2y(2) = b2y(2) + self%m * self%g * self%h * c - mh * a * s
        dety = 0.0_dp
        dety(2) = -2.0_dp * mh * mh * c * s
        ! P = I_O b1 - m h S b2, Q = m b2 - m h S b1; v'' = P/det, theta'' = Q/det
        py = self%i_o * b1y - mh * s * b2y
        py(2) = py(2) - mh * c * b2
        qy = self%m * b2y - mh * s * b1y
        qy(2) = qy(2) - mh * c * b1
        dfdy = 0.0_dp
        dfdy(1, 3) = 1.0_dp
        dfdy(2, 4) = 1.0_dp
        dfdy(3, 1:4) = (py - vdd * dety) / det
        dfdy(4, 1:4) = (qy - thdd * dety) / det
        dfdy(5, 1:4) = ct%dn * y(3) - ct%dm * thd
        dfdy(5, 3) = dfdy(5, 3) + ct%n
        dfdy(5, 4) = dfdy(5, 4) - ct%m
        dfdy(6, 2) = -self%m * a * self%h * s * thd
        dfdy(6, 4) = self%m * a * self%h * c
    end subroutine wr_jacobian

    !> Event functions (W.48)-(W.50): 1, 2 penetration at the +r, -r edges (m); 3, 4 the
    !> pressure there (Pa); 5 theta; 6 theta_overturn - |theta|; 7 pi/2 - |theta|;
    !> 10 + i: the rate of event i (1, 2, 5, 6, 7), for the turning points.
    function wr_event(self, i, t, y) result(g)
        class(wr_ode_t), intent(inout) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp) :: g
        real(dp) :: kb, b
        integer :: stat
        associate(unused => t)
        end associate
        select case (i)
        case (EV_EDGE_HI)
            g = y(1) - self%r * sin(y(2))
        case (EV_EDGE_LO)
            g = y(1) + self%r * sin(y(2))
        case (EV_Q_HI, EV_Q_LO)
            kb = self%k
            if (self%k_method == K_VARYING) then
                b = contact_width(self, y)
                if (b > 0.0_dp) call varying_modulus(self%footing, self%r, self%alpha, &
                                                     self%k, b, kb, stat, reading=self%reading)
            end if
            if (i == EV_Q_HI) then
                g = kb * (y(1) - self%r * sin(y(2))) + self%c * (y(3) - self%r * cos(y(2)) * y(4))
            else
                g = kb * (y(1) + self%r * sin(y(2))) + self%c * (y(3) + self%r * cos(y(2)) * y(4))
            end if
        case (EV_THETA)
            g = y(2)
        case (EV_OVERTURN)
            g = self%theta_ov - abs(y(2))
        case (EV_CAP)
            g = half_pi - abs(y(2))
        case (EV_TURN + EV_EDGE_HI)
            g = y(3) - self%r * cos(y(2)) * y(4)
        case (EV_TURN + EV_EDGE_LO)
            g = y(3) + self%r * cos(y(2)) * y(4)
        case (EV_TURN + EV_THETA)
            g = y(4)
        case (EV_TURN + EV_OVERTURN, EV_TURN + EV_CAP)
            g = -sign(1.0_dp, y(2)) * y(4)
        case default
            g = 0.0_dp
        end select
    end function wr_event

    !> All active event functions g (as wr_event) and the rates d of 1, 2, 5, 6, 7 at y,
    !> from one sine and cosine.
    subroutine event_values(sys, active, y, g, d)
        class(wr_ode_t), intent(inout) :: sys
        logical, intent(in) :: active(NEV)
        real(dp), intent(in) :: y(:)
        real(dp), intent(out) :: g(NEV), d(NEV)
        real(dp) :: s, c, rs, rct, at
        s = sin(y(2))
        c = cos(y(2))
        rs = sys%r * s
        rct = sys%r * c * y(4)
        at = abs(y(2))
        g(EV_EDGE_HI) = y(1) - rs
        g(EV_EDGE_LO) = y(1) + rs
        d(EV_EDGE_HI) = y(3) - rct
        d(EV_EDGE_LO) = y(3) + rct
        g(EV_Q_HI) = 0.0_dp
        g(EV_Q_LO) = 0.0_dp
        d(EV_Q_HI) = 0.0_dp
        d(EV_Q_LO) = 0.0_dp
        if (active(EV_Q_HI)) then
            if (sys%k_method == K_VARYING) then
                g(EV_Q_HI) = sys%event(EV_Q_HI, 0.0_dp, y)
                g(EV_Q_LO) = sys%event(EV_Q_LO, 0.0_dp, y)
            else
                g(EV_Q_HI) = sys%k * g(EV_EDGE_HI) + sys%c * d(EV_EDGE_HI)
                g(EV_Q_LO) = sys%k * g(EV_EDGE_LO) + sys%c * d(EV_EDGE_LO)
            end if
        end if
        g(EV_THETA) = y(2)
        d(EV_THETA) = y(4)
        g(EV_OVERTURN) = sys%theta_ov - at
        g(EV_CAP) = half_pi - at
        d(EV_OVERTURN) = -sign(1.0_dp, y(2)) * y(4)
        d(EV_CAP) = d(EV_OVERTURN)
    end subroutine event_values

    !> Geometric contact width at y (m).
    function contact_width(sys, y) result(b)
        class(wr_ode_t), intent(inout) :: sys
        real(dp), intent(in) :: y(:)
        real(dp) :: b
        type(end_t) :: glo, ghi
        real(dp) :: s
        logical :: empty
        s = sin(y(2))
        glo = end_t(0.0_dp, 2.0_dp * sys%r, END_EDGE)
        ghi = end_t(2.0_dp * sys%r, 0.0_dp, END_EDGE)
        empty = .false.
        call restrict(y(1) + sys%r * s, y(1) - sys%r * s, 2.0_dp * sys%r, END_DELTA, glo, ghi, &
                      empty)
        b = 0.0_dp
        if (empty) return
        if (glo%kind == END_EDGE) then
            b = ghi%d_lo
        else
            b = glo%d_hi
        end if
    end function contact_width

    !> Total energy T + V_g + U (J) (W.39) at y, with the contact already evaluated.
    pure function energy(sys, y, u) result(e)
        type(wr_ode_t), intent(in) :: sys
        real(dp), intent(in) :: y(:), u
        real(dp) :: e
        real(dp) :: s, c
        s = sin(y(2))
        c = cos(y(2))
        e = 0.5_dp * sys%m * (y(3) * y(3) + 2.0_dp * sys%h * s * y(3) * y(4)) &
            + 0.5_dp * sys%i_o * y(4) * y(4) + sys%m * sys%g * (sys%h * c - y(1)) + u
    end function energy

    ! ------------------------------------------------------------------------------
    ! The event-driven integrator
    ! ------------------------------------------------------------------------------

    subroutine simulate(st, it, accel, y0, t_grid, hist, run, stat, errmsg)
        type(wr_state_t), intent(inout) :: st
        type(piece_iter_t), intent(inout) :: it
        real(dp), intent(in) :: accel(:)
        real(dp), intent(in) :: y0(NY)
        real(dp), intent(in) :: t_grid(:)
        real(dp), intent(inout) :: hist(:, :)
        type(winkler_run_t), intent(inout) :: run
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        type(piece_t) :: piece
        type(contact_t) :: ct
        integer :: src, why, i
        logical :: found
        real(dp) :: a_end

        stat = SEISPULSE_SUCCESS
        call empty_run(run)
        ! a fresh integrator for every run (a map's cells share the allocation)
        call st%ode%init(NY, st%rtol, st%atol, st%stat)
        if (st%stat /= SEISPULSE_SUCCESS) then
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'winkler_rock: integrator ' &
                           //'set-up failed (a bug)')
            return
        end if
        if (allocated(st%tg)) deallocate(st%tg)
        allocate(st%tg, source=t_grid)
        st%ng = size(t_grid)
        st%ig = 1
        if (.not. allocated(st%imp)) allocate(st%imp(16), st%pk_n(16), st%pk_m(16))
        st%n_imp = 0
        st%open_imp = 0
        st%steps = 0
        st%t = 0.0_dp
        st%y = y0
        st%y(5:6) = 0.0_dp
        st%h = 0.01_dp / st%p
        st%done = .false.
        st%free = .false.
        st%safe = .false.
        st%lifted = .false.
        st%swing = abs(y0(2))
        st%e_err = 0.0_dp
        st%run_n = 0.0_dp
        st%run_m = 0.0_dp
        st%t_out_cross = ieee_value(1.0_dp, ieee_quiet_nan)
        src = st%sys%gr%src
        a_end = 0.0_dp
        st%sys%gr%src = GR_NONE
        st%sys%stat = SEISPULSE_SUCCESS
        call contact(st%sys, st%y, ct, .false.)
        st%u0 = ct%u
        st%e0 = energy(st%sys, st%y, ct%u)
        st%e_scale = max(abs(st%e0 - st%e_rest), st%sys%m * st%sys%g * st%sys%r * 1.0e-12_dp)
        call init_sides(st)
        if (st%side(EV_EDGE_HI) < 0 .or. st%side(EV_EDGE_LO) < 0) then
            st%lifted = .true.
            run%t_uplift = 0.0_dp
            if (st%side(EV_EDGE_HI) < 0 .and. st%side(EV_EDGE_LO) < 0) run%t_lift_off = 0.0_dp
        end if
        run%theta_max = abs(st%y(2))
        do while (st%ig <= st%ng)
            if (st%tg(st%ig) > 0.0_dp) exit
            call put_state(st, st%tg(st%ig), st%y, hist(:, st%ig), run)
            st%ig = st%ig + 1
        end do
        st%sys%gr%src = src

        if (src /= GR_NONE) then
            pieces: do
                call next_piece(it, accel, 'winkler_rock', piece, found, stat, errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                if (.not. found) exit pieces
                ! a_g jumps (or the ground is switched off before the piece): the right-hand
                ! side changes other than through (t, y), so Radau starts afresh
                if (st%t < piece%ta .or. abs(piece%aa - a_end) > 0.0_dp) call st%ode%restart()
                st%sys%gr%ta = piece%ta
                st%sys%gr%tb = piece%tb
                st%sys%gr%aa = piece%aa
                st%sys%gr%ab = piece%ab
                st%sys%gr%slope = piece%slope
                if (st%t < piece%ta) then
                    st%sys%gr%src = GR_NONE
                    call advance(st, hist, run, min(piece%ta, st%t_lim), why)
                    st%sys%gr%src = src
                    call st%ode%restart()
                    if (handle(why)) exit pieces
                end if
                a_end = piece%ab
                call advance(st, hist, run, min(piece%tb, st%t_lim), why)
                if (handle(why)) exit pieces
            end do pieces
        end if
        if (.not. st%done) then
            if (abs(a_end) > 0.0_dp) call st%ode%restart()
            st%sys%gr%src = GR_NONE
            st%free = .true.
            call free_checks(st, run, why)
            if (.not. handle(why)) then
                call advance(st, hist, run, st%t_lim, why)
                if (.not. handle(why)) call finish(st, hist, run, WHY_LIMIT)
            end if
        end if
        if (st%stat /= SEISPULSE_SUCCESS .or. st%sys%stat /= SEISPULSE_SUCCESS) then
            if (.not. allocated(st%msg)) st%msg = 'winkler_rock: the varying modulus failed' &
                                                 //' (a bug)'
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, st%msg)
            return
        end if
        run%n_impacts = st%n_imp
        run%n_steps = st%steps
        run%energy_error = st%e_err / st%e_scale
        deallocate(run%t_impacts, run%impact_normal_peak, run%impact_moment_peak)
        allocate(run%t_impacts(st%n_imp), run%impact_normal_peak(st%n_imp), &
                 run%impact_moment_peak(st%n_imp))
        do i = 1, st%n_imp
            run%t_impacts(i) = st%imp(i)
            run%impact_normal_peak(i) = st%pk_n(i)
            run%impact_moment_peak(i) = st%pk_m(i)
        end do

    contains

        !> Act on the reason `advance` stopped; true when the run is over.
        logical function handle(w)
            integer, intent(in) :: w
            integer :: w2
            handle = .true.
            if (st%done) return
            select case (w)
            case (WHY_REACHED)
                handle = .false.
                if (.not. st%t < st%t_lim) then
                    ! the limit at (or after) the end of the excitation: its overturning
                    ! rule and the energy criterion still decide the outcome there
                    w2 = WHY_REACHED
                    if (.not. st%free .and. .not. st%t < st%t_exc) then
                        st%free = .true.
                        call free_checks(st, run, w2)
                    end if
                    if (w2 == WHY_REACHED) w2 = WHY_LIMIT
                    call finish(st, hist, run, w2)
                    handle = .true.
                end if
            case default
                call finish(st, hist, run, w)
            end select
        end function handle

    end subroutine simulate

    !> Sides of the event functions at the start: +-1, 0 where undetermined (theta = 0).
    subroutine init_sides(st)
        type(wr_state_t), intent(inout) :: st
        integer :: i
        real(dp) :: g
        st%active = .true.
        st%active(EV_Q_HI) = st%sys%c > 0.0_dp
        st%active(EV_Q_LO) = st%sys%c > 0.0_dp
        st%active(EV_OVERTURN) = ieee_is_finite(st%sys%theta_ov)
        st%side = 0
        do i = 1, NEV
            if (.not. st%active(i)) cycle
            g = st%sys%event(i, st%t, st%y)
            st%side(i) = side_of(g)
        end do
        ! an edge exactly on the surface counts as out of contact (q = 0 there)
        if (st%side(EV_EDGE_HI) == 0) st%side(EV_EDGE_HI) = -1
        if (st%side(EV_EDGE_LO) == 0) st%side(EV_EDGE_LO) = -1
        if (st%side(EV_Q_HI) == 0) st%side(EV_Q_HI) = -1
        if (st%side(EV_Q_LO) == 0) st%side(EV_Q_LO) = -1
    end subroutine init_sides

    elemental integer function side_of(g)
        real(dp), intent(in) :: g
        if (g > 0.0_dp) then
            side_of = 1
        else if (g < 0.0_dp) then
            side_of = -1
        else
            side_of = 0
        end if
    end function side_of

    !> After the excitation: overturning (beyond theta_overturn, moving away) or the
    !> energy criterion (W.52)-(W.55).
    subroutine free_checks(st, run, why)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        integer, intent(out) :: why
        type(contact_t) :: ct
        why = WHY_REACHED
        if (.not. st%free) return
        if (ieee_is_finite(st%sys%theta_ov)) then
            if (abs(st%y(2)) >= st%sys%theta_ov .and. st%y(2) * st%y(4) > 0.0_dp) then
                if (ieee_is_nan(st%t_out_cross)) st%t_out_cross = st%t
                why = WHY_OVERTURN
                return
            end if
        end if
        if (st%proof .and. .not. st%safe) then
            if (abs(st%y(2)) < st%sys%theta_ov) then
                call contact(st%sys, st%y, ct, .false.)
                if (energy(st%sys, st%y, ct%u) - st%e_rest &
                    < (1.0_dp - barrier_margin) * st%barrier) then              ! (W.55)
                    st%safe = .true.
                    run%t_safe = st%t
                end if
            end if
        end if
        if (st%safe .and. st%ig > st%ng) why = WHY_SAFE
    end subroutine free_checks

    !> Integrate from (t, y) up to t_stop: events, output points, checks.
    subroutine advance(st, hist, run, t_stop, why)
        type(wr_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(winkler_run_t), intent(inout) :: run
        real(dp), intent(in) :: t_stop
        integer, intent(out) :: why
        real(dp) :: hh, t_new, y_new(NY), f_new(NY), err, fac, x_ev, yv(NY), ys(NY, 0:NSAMP), &
                    xs(0:NSAMP), t_ev
        integer :: kk, i, ev
        logical :: clamped, rejected, crossed(NEV)

        why = WHY_REACHED
        call st%sys%rhs(st%t, st%y, st%f)
        rejected = .false.
        do i = 0, NSAMP
            xs(i) = real(i, dp) / real(NSAMP, dp)
        end do
        do kk = 1, st%max_steps
            if (.not. st%t < t_stop) return
            if (st%steps >= st%max_steps) then
                why = WHY_LIMIT
                return
            end if
            st%steps = st%steps + 1
            st%h = min(st%h, st%h_max)
            clamped = .not. st%h < t_stop - st%t
            if (clamped) then
                t_new = t_stop
            else
                t_new = st%t + st%h
            end if
            hh = t_new - st%t
            if (hh < min_step(st, st%t)) then
                if (clamped) then
                    ! a sliver of a piece below the time resolution: step over it
                    st%t = t_new
                    cycle
                end if
                why = WHY_LIMIT
                return
            end if
            call st%ode%step(st%sys, st%t, st%y, st%f, hh, t_new, y_new, f_new, err)
            if (.not. (err <= 1.0_dp .and. all(ieee_is_finite(y_new)) &
                       .and. abs(y_new(2)) < pi)) then
                rejected = .true.
                st%h = hh * step_factor(st, err)
                if (err <= 1.0_dp) st%h = 0.25_dp * hh
                cycle
            end if
            fac = step_factor(st, err)
            if (rejected) fac = min(fac, 1.0_dp)
            rejected = .false.
            call st%ode%dense_setup(st%sys, st%t, st%y, st%f, hh, y_new, f_new)
            ys(:, 0) = st%y
            ys(:, NSAMP) = y_new
            do i = 1, NSAMP - 1
                call st%ode%value(xs(i), ys(:, i))
            end do
            call scan_events(st, hh, xs, ys, ev, x_ev, crossed)
            if (st%stat /= SEISPULSE_SUCCESS) then
                why = WHY_ERROR
                return
            end if
            if (ev == 0) then
                call theta_extremes(st, run, xs, ys, NSAMP)
                if (st%open_imp > 0) call sample_step(st, run, hh, xs, ys, NSAMP - 1)
            else
                t_ev = st%t + x_ev * hh
                call st%ode%value(x_ev, yv)
                ! samples before the event, then the event point
                do i = 1, NSAMP
                    if (xs(i) >= x_ev) exit
                end do
                call theta_extremes(st, run, xs, ys, i - 1)
                if (st%open_imp > 0) call sample_step(st, run, hh, xs, ys, i - 1)
            end if
            ! output points inside the step (up to the event)
            do while (st%ig <= st%ng)
                if (ev == 0) then
                    if (st%tg(st%ig) > t_new) exit
                else
                    if (st%tg(st%ig) > t_ev) exit
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
            if (ev == 0) then
                st%t = t_new
                st%y = y_new
                st%f = f_new
                call step_end(st, run)
                call free_checks(st, run, why)
                if (why /= WHY_REACHED) return
                cycle
            end if
            call st%ode%value(x_ev, yv)
            st%t = t_ev
            st%y = yv
            call st%sys%rhs(st%t, st%y, st%f)
            call on_events(st, run, crossed, why)
            if (why /= WHY_REACHED) return
            call step_end(st, run)
            call free_checks(st, run, why)
            if (why /= WHY_REACHED) return
        end do
        why = WHY_LIMIT
    end subroutine advance

    !> The step-size factor after a step with error norm err.
    pure function step_factor(st, err) result(fac)
        type(wr_state_t), intent(in) :: st
        real(dp), intent(in) :: err
        real(dp) :: fac
        fac = ode_radau5_factor(err, st%ode%newton_iters, st%ode%theta)
    end function step_factor

    !> End of the excitation of a (valid) pulse (s): its end time, or for the Ricker
    !> wavelet the end of its last piece, x = pi f_p (t - t0) = 10 (seispulse_pieces).
    pure function excitation_end(p) result(t_end)
        type(pulse_t), intent(in) :: p
        real(dp) :: t_end
        if (p%kind == PULSE_RICKER) then
            t_end = p%t0 + ricker_x_cut / (pi * p%freq)
        else
            t_end = pulse_end_time(p)
        end if
    end function excitation_end

    pure function min_step(st, t) result(h)
        type(wr_state_t), intent(in) :: st
        real(dp), intent(in) :: t
        real(dp) :: h
        h = 16.0_dp * epsilon(t) * max(abs(t), 1.0e-3_dp / st%p)
    end function min_step

    !> The first event in the step (W.50): for each active event function, the samples
    !> xs (values ys) are searched for a change from its side, and each sub-interval whose
    !> rate turns towards the boundary and back is searched at the turning point. ev = 0:
    !> none; else x_ev, and `crossed` marks every event function whose side differs at x_ev.
    subroutine scan_events(st, hh, xs, ys, ev, x_ev, crossed)
        type(wr_state_t), intent(inout) :: st
        real(dp), intent(in) :: hh, xs(0:NSAMP), ys(NY, 0:NSAMP)
        integer, intent(out) :: ev
        real(dp), intent(out) :: x_ev
        logical, intent(out) :: crossed(NEV)
        real(dp) :: gall(NEV, 0:NSAMP), dall(NEV, 0:NSAMP), gs(0:NSAMP), ds(0:NSAMP), x, ga, &
                    xt, gt, yv(NY)
        integer :: i, k, sd, k2
        logical :: has_turn, turn
        real(dp) :: gx, dx
        ev = 0
        x_ev = 2.0_dp
        crossed = .false.
        do k = 0, NSAMP
            call event_values(st%sys, st%active, ys(:, k), gall(:, k), dall(:, k))
        end do
        do i = 1, NEV
            if (.not. st%active(i)) cycle
            if ((i == EV_Q_HI .and. st%side(EV_EDGE_HI) < 0) .or. &
                (i == EV_Q_LO .and. st%side(EV_EDGE_LO) < 0)) then
                ! the pressure at an edge out of contact is no structure: its side follows
                if (side_of(gall(i, NSAMP)) /= 0) st%side(i) = side_of(gall(i, NSAMP))
                cycle
            end if
            sd = st%side(i)
            has_turn = i == EV_EDGE_HI .or. i == EV_EDGE_LO .or. i == EV_THETA .or. &
                       i == EV_OVERTURN .or. i == EV_CAP
            gs = gall(i, :)
            ds = dall(i, :)
            if (sd == 0) then
                ! undetermined (theta = 0 at rest): the first nonzero sign, no event
                do k = 1, NSAMP
                    if (side_of(gs(k)) /= 0) then
                        st%side(i) = side_of(gs(k))
                        exit
                    end if
                end do
                cycle
            end if
            x = -1.0_dp
            do k = 1, NSAMP
                if (xs(k - 1) >= x_ev) exit
                ga = gs(k - 1)
                if (real(sd, dp) * gs(k) < 0.0_dp) then
                    if (.not. real(sd, dp) * ga > 0.0_dp) then
                        ! on or across the boundary at the start of the step (just after an
                        ! event of this function, within the rounding): back at once
                        x = xs(k - 1)
                    else
                        call locate(st, i, hh, xs(k - 1), xs(k), ga, gs(k), x)
                    end if
                    exit
                end if
                turn = has_turn
                ! |theta| has a kink, not a turning point, where theta changes sign
                if (i == EV_OVERTURN .or. i == EV_CAP) turn = ys(2, k - 1) * ys(2, k) > 0.0_dp
                if (turn) then
                    if (real(sd, dp) * ds(k - 1) < 0.0_dp .and. real(sd, dp) * ds(k) > 0.0_dp) then
                        ! towards the boundary, then away: search at the turning point
                        call locate(st, EV_TURN + i, hh, xs(k - 1), xs(k), ds(k - 1), ds(k), xt)
                        if (st%stat /= SEISPULSE_SUCCESS) return
                        call st%ode%value(xt, yv)
                        gt = st%sys%event(i, st%t + xt * hh, yv)
                        if (real(sd, dp) * gt < 0.0_dp) then
                            if (.not. real(sd, dp) * ga > 0.0_dp) then
                                x = xs(k - 1)
                            else
                                call locate(st, i, hh, xs(k - 1), xt, ga, gt, x)
                            end if
                            exit
                        end if
                    end if
                end if
            end do
            if (st%stat /= SEISPULSE_SUCCESS) return
            if (x >= 0.0_dp .and. x < x_ev) then
                ! the event state strictly on the new side (the root may sit on the old side
                ! of g within the rounding): forward in doubling steps, at most to xs(k)
                dx = 16.0_dp * epsilon(1.0_dp)
                do k2 = 1, 64
                    call st%ode%value(x, yv)
                    gx = st%sys%event(i, st%t + x * hh, yv)
                    if (real(sd, dp) * gx < 0.0_dp .or. .not. x < xs(k)) exit
                    x = min(x + dx, xs(k))
                    dx = 2.0_dp * dx
                end do
                if (x < x_ev) then
                    x_ev = x
                    ev = i
                end if
            end if
        end do
        if (ev == 0) return
        ! every event function whose side has changed by x_ev
        call st%ode%value(x_ev, yv)
        do i = 1, NEV
            if (.not. st%active(i) .or. st%side(i) == 0) cycle
            if ((i == EV_Q_HI .and. st%side(EV_EDGE_HI) < 0) .or. &
                (i == EV_Q_LO .and. st%side(EV_EDGE_LO) < 0)) cycle
            if (i == ev) then
                crossed(i) = .true.
            else
                crossed(i) = real(st%side(i), dp) * st%sys%event(i, st%t + x_ev * hh, yv) < 0.0_dp
            end if
        end do
    end subroutine scan_events

    !> Root of event function i on the dense output in [xa, xb] (values fa, fb there).
    subroutine locate(st, i, hh, xa, xb, fa, fb, x)
        type(wr_state_t), intent(inout), target :: st
        integer, intent(in) :: i
        real(dp), intent(in) :: hh, xa, xb, fa, fb
        real(dp), intent(out) :: x
        type(root_fn_t) :: fn
        character(len=120) :: rmsg
        rmsg = ''
        fn%st => st
        fn%i = i
        fn%hh = hh
        ! an absolute tolerance of a few ulps of the step fraction (~1e-15 hh): a root next
        ! to x = 0 would otherwise ask for a relative accuracy below the rounding of g
        call find_root(fn, xa, xb, x, st%stat, rmsg, xtol=16.0_dp * epsilon(1.0_dp), &
                       fa_known=fa, fb_known=fb)
        x = min(max(x, xa), xb)
        if (st%stat /= SEISPULSE_SUCCESS) then
            st%msg = 'winkler_rock: event location failed after t = '//real_str(st%t) &
                     //' (event '//int_str(i)//', bracket '//real_str(xa)//' '//real_str(xb) &
                     //', values '//real_str(fa)//' '//real_str(fb)//'): '//trim(rmsg) &
                     //' (a bug)'
            st%stat = SEISPULSE_INTERNAL
        end if
    end subroutine locate

    !> Event function i on the dense output of the step from st%t of size hh.
    function root_eval(self, x) result(g)
        class(root_fn_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: g
        real(dp) :: y(NY)
        call self%st%ode%value(x, y)
        g = self%st%sys%event(self%i, self%st%t + x * self%hh, y)
    end function root_eval

    !> The events at st%t (W.48)-(W.52): contact changes at the edges, impacts, the
    !> overturning angle and the cap.
    subroutine on_events(st, run, crossed, why)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        logical, intent(in) :: crossed(NEV)
        integer, intent(out) :: why
        real(dp), allocatable :: tmp(:)
        integer :: i, n
        logical :: was_free
        why = WHY_REACHED
        was_free = st%side(EV_EDGE_HI) < 0 .and. st%side(EV_EDGE_LO) < 0
        do i = 1, NEV
            if (crossed(i)) st%side(i) = -st%side(i)
        end do
        if (crossed(EV_EDGE_HI) .or. crossed(EV_EDGE_LO)) then
            if ((crossed(EV_EDGE_HI) .and. st%side(EV_EDGE_HI) < 0) .or. &
                (crossed(EV_EDGE_LO) .and. st%side(EV_EDGE_LO) < 0)) then
                ! an edge lifted: uplift (W.48); the impact phase ends
                st%lifted = .true.
                st%open_imp = 0
                if (ieee_is_nan(run%t_uplift)) run%t_uplift = st%t
                if (st%side(EV_EDGE_HI) < 0 .and. st%side(EV_EDGE_LO) < 0 .and. &
                    ieee_is_nan(run%t_lift_off)) run%t_lift_off = st%t
            end if
            if ((crossed(EV_EDGE_HI) .and. st%side(EV_EDGE_HI) > 0) .or. &
                (crossed(EV_EDGE_LO) .and. st%side(EV_EDGE_LO) > 0)) then
                ! an edge touched down: the impact peaks are counted from here
                st%run_n = 0.0_dp
                st%run_m = 0.0_dp
                if (was_free .and. ieee_is_nan(run%t_touch_down)) run%t_touch_down = st%t
            end if
        end if
        if (crossed(EV_THETA)) then
            st%open_imp = 0
            if (st%lifted .and. st%swing > st%theta_imp) then
                ! an impact (W.49)
                st%n_imp = st%n_imp + 1
                n = size(st%imp)
                if (st%n_imp > n) then
                    allocate(tmp(2 * n))
                    tmp(1:n) = st%imp
                    call move_alloc(tmp, st%imp)
                    allocate(tmp(2 * n))
                    tmp(1:n) = st%pk_n
                    call move_alloc(tmp, st%pk_n)
                    allocate(tmp(2 * n))
                    tmp(1:n) = st%pk_m
                    call move_alloc(tmp, st%pk_m)
                end if
                st%imp(st%n_imp) = st%t
                st%pk_n(st%n_imp) = st%run_n
                st%pk_m(st%n_imp) = st%run_m
                st%open_imp = st%n_imp
            end if
            st%lifted = .false.
            st%swing = 0.0_dp
        end if
        if (crossed(EV_OVERTURN) .and. st%side(EV_OVERTURN) < 0) then
            st%t_out_cross = st%t
            if (st%free) then
                why = WHY_OVERTURN
                return
            end if
        end if
        if (crossed(EV_CAP)) then
            if (ieee_is_nan(st%t_out_cross)) st%t_out_cross = st%t
            why = WHY_OVERTURN
        end if
    end subroutine on_events

    !> Peaks and maxima at the samples 1..k of a step.
    subroutine sample_step(st, run, hh, xs, ys, k)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        real(dp), intent(in) :: hh, xs(0:NSAMP), ys(NY, 0:NSAMP)
        integer, intent(in) :: k
        integer :: i
        do i = 1, k
            call track(st, run, st%t + xs(i) * hh, ys(:, i))
        end do
    end subroutine sample_step

    !> The extremes of theta inside the step (theta' = 0 between the samples 0..k of the
    !> dense output, located by the root finder) into run%theta_max: the largest |theta| is
    !> a turning point or an end of a step, never only a sample near it.
    subroutine theta_extremes(st, run, xs, ys, k)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        real(dp), intent(in) :: xs(0:NSAMP), ys(NY, 0:NSAMP)
        integer, intent(in) :: k
        real(dp) :: x, yx(NY)
        integer :: i, stat
        do i = 1, k
            if (ys(4, i - 1) * ys(4, i) < 0.0_dp) then
                call st%ode%locate(4, 1.0_dp, 0.0_dp, xs(i - 1), xs(i), ys(4, i - 1), &
                                   ys(4, i), x, stat)
                if (stat == SEISPULSE_SUCCESS) then
                    call st%ode%value(x, yx)
                    run%theta_max = max(run%theta_max, abs(yx(2)))
                    st%swing = max(st%swing, abs(yx(2)))
                end if
            end if
        end do
    end subroutine theta_extremes

    !> Maxima of |theta| and N, the impact peaks and the energy balance at (t, y).
    subroutine track(st, run, t, y)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        real(dp), intent(in) :: t, y(NY)
        type(contact_t) :: ct
        real(dp) :: e, d
        associate(unused => t)
        end associate
        call contact(st%sys, y, ct, .false.)
        run%theta_max = max(run%theta_max, abs(y(2)))
        st%swing = max(st%swing, abs(y(2)))
        run%normal_max = max(run%normal_max, ct%n)
        st%run_n = max(st%run_n, ct%n)
        st%run_m = max(st%run_m, abs(ct%m))
        if (st%open_imp > 0) then
            st%pk_n(st%open_imp) = max(st%pk_n(st%open_imp), ct%n)
            st%pk_m(st%open_imp) = max(st%pk_m(st%open_imp), abs(ct%m))
        end if
        e = energy(st%sys, y, ct%u)
        d = y(5) - (ct%u - st%u0)                                            ! (W.41)
        st%e_scale = max(st%e_scale, abs(e - st%e_rest), abs(y(6)), abs(d))
        st%e_err = max(st%e_err, abs(e + d - st%e0 - y(6)))
    end subroutine track

    subroutine step_end(st, run)
        type(wr_state_t), intent(inout) :: st
        type(winkler_run_t), intent(inout) :: run
        call track(st, run, st%t, st%y)
    end subroutine step_end

    !> The output columns at (t, y).
    subroutine put_state(st, t, y, col, run)
        type(wr_state_t), intent(inout) :: st
        real(dp), intent(in) :: t, y(NY)
        real(dp), intent(out) :: col(:)
        type(winkler_run_t), intent(inout) :: run
        type(contact_t) :: ct
        call contact(st%sys, y, ct, .false.)
        col(1:4) = y(1:4)
        col(WR_OUT_WIDTH) = ct%width
        col(WR_OUT_NORMAL) = ct%n
        col(WR_OUT_MOMENT) = ct%m
        col(WR_OUT_ACCEL) = ground_accel(st%sys%gr, t)
        col(WR_OUT_ENERGY) = energy(st%sys, y, ct%u)
        col(WR_OUT_WORK) = y(6)
        col(WR_OUT_DISSIPATED) = y(5) - (ct%u - st%u0)
        run%normal_max = max(run%normal_max, ct%n)
    end subroutine put_state

    !> End of the run: the outcome, and the output points after it.
    subroutine finish(st, hist, run, why)
        type(wr_state_t), intent(inout) :: st
        real(dp), intent(inout) :: hist(:, :)
        type(winkler_run_t), intent(inout) :: run
        integer, intent(in) :: why
        real(dp) :: nan
        st%done = .true.
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        run%t_end = st%t
        run%theta_max = max(run%theta_max, abs(st%y(2)))   ! the final state (an overturn)
        select case (why)
        case (WHY_OVERTURN)
            select case (st%n_imp)
            case (0)
                run%outcome = WR_RUN_OVERTURN_NO_IMPACT
            case (1)
                run%outcome = WR_RUN_OVERTURN_ONE_IMPACT
            case default
                run%outcome = WR_RUN_OVERTURN_IMPACTS
            end select
            run%t_overturn = st%t_out_cross
            do while (st%ig <= st%ng)
                hist(:, st%ig) = nan
                hist(WR_OUT_THETA, st%ig) = sign(half_pi, st%y(2))
                st%ig = st%ig + 1
            end do
        case default
            if (st%safe) then
                run%outcome = WR_RUN_SAFE
            else
                run%outcome = WR_RUN_TIME_LIMIT
            end if
            do while (st%ig <= st%ng)
                hist(:, st%ig) = nan
                st%ig = st%ig + 1
            end do
        end select
    end subroutine finish

end module seispulse_winkler_rock
