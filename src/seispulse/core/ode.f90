!> Explicit Runge-Kutta integration of y' = f(t, y) for any state dimension: the
!> Dormand & Prince 8(5,3) pair (Hairer's DOP853) with its 5th/3rd-order error estimator
!> and 7th-order dense output, and event location on the dense output.
!>
!> A model extends `ode_system` with its right-hand side `rhs(t, y, dydt)` (and, if it
!> has any, event functions g_i(t, y) through `event`); `ode_dop853_t` holds the stages
!> of the last step, so that one allocation at `init` serves a whole run:
!>     call ode%init(n, rtol, atol, stat)
!>     call ode%step(sys, t, y, f, h, t_new, y_new, f_new, err)  ! err <= 1: accept
!>     call ode%dense_setup(sys, t, y, f, h, y_new, f_new)       ! 7th-order y(t + x h)
!>     call ode%value(x, yx)
!>     call ode%locate(comp, sgn, level, xa, xb, fa, fb, x, stat)   ! sgn y(comp) = level
!>     call ode%locate_event(sys, i, xa, xb, ga, gb, x, stat)       ! g_i(t, y) = 0
!> The step-size policy stays with the caller (it knows its events and breakpoints);
!> `ode_dop853_factor` gives Hairer's factor 0.9 err^(-1/8) within [0.2, 10].
!>
!> Method (Hairer, Norsett & Wanner, Solving ODEs I, II.10 and II.6): 12 stages for the
!> 8th-order solution, the 13th (f at the new point) for the error estimate
!>     err = |h| E5 / sqrt(n (E5 + 0.01 E3)),  E_q = sum_i (e_q,i / sc_i)^2,
!>     sc_i = atol_i + rtol max(|y_i|, |y_new,i|),
!> and 3 more for the dense output
!>     y(t + x h) = y0 + x (r1 + (1-x) (r2 + x (r3 + (1-x) (r4 + x (r5 + (1-x) (r6 + x r7)))))).
!> Stage 12 and the end of the step are evaluated at t_new exactly (a breakpoint of the
!> right-hand side, if the caller clamps the step there).
module seispulse_ode
    use seispulse_kinds, only: dp
    use seispulse_checks, only: in_open, finite_at_least
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_roots, only: scalar_function, find_root
    implicit none
    private

    public :: ode_system, ode_dop853_t, ode_dense_t, ode_dop853_factor, ode_fd_jacobian
    public :: ode_dense_base, ode_locate, ode_locate_event

    !> A system y' = f(t, y) of any dimension; optional event functions g_i(t, y) and the
    !> Jacobian df/dy (used by the implicit integrator of seispulse_radau; by default
    !> forward differences, a model overrides it with its exact Jacobian).
    type, abstract :: ode_system
    contains
        procedure(ode_rhs), deferred :: rhs
        procedure :: event => ode_no_event
        procedure :: jacobian => ode_fd_jacobian
    end type ode_system

    abstract interface
        !> dydt = f(t, y). For a few states, write dydt in one assignment from a local
        !> array: the step reads the components two at a time, and a pair of separate
        !> scalar stores read back as one pair stalls the processor.
        subroutine ode_rhs(self, t, y, dydt)
            import :: ode_system, dp
            class(ode_system), intent(inout) :: self  !! the system and its parameters
            real(dp), intent(in) :: t                 !! time
            real(dp), contiguous, intent(in) :: y(:)      !! state, n
            real(dp), contiguous, intent(out) :: dydt(:)  !! derivative, n
        end subroutine ode_rhs
    end interface

    !> Dense output of a step of any integrator: y(t0 + x h), 0 <= x <= 1, and, as a
    !> function of x for the root finder, sgn y(comp) - level (`ode_locate`,
    !> `ode_locate_event` find the roots).
    type, abstract, extends(scalar_function) :: ode_dense_base
        integer :: n = 0                      !! state dimension
        real(dp) :: t0 = 0.0_dp               !! start of the step
        real(dp) :: h = 0.0_dp                !! its size
        integer :: comp = 1                   !! component sought by `eval`
        real(dp) :: sgn = 1.0_dp              !! its sign
        real(dp) :: level = 0.0_dp            !! its level
    contains
        procedure(dense_value_iface), deferred :: value
        procedure(dense_component_iface), deferred :: component
        procedure :: eval => dense_eval
    end type ode_dense_base

    abstract interface
        !> y(t0 + x h).
        pure subroutine dense_value_iface(self, x, y)
            import :: ode_dense_base, dp
            class(ode_dense_base), intent(in) :: self  !! the dense output
            real(dp), intent(in) :: x                  !! fraction of the step
            real(dp), intent(out) :: y(:)              !! state, n
        end subroutine dense_value_iface
        !> Component m of y(t0 + x h).
        pure function dense_component_iface(self, m, x) result(v)
            import :: ode_dense_base, dp
            class(ode_dense_base), intent(in) :: self  !! the dense output
            integer, intent(in) :: m                   !! component, 1..n
            real(dp), intent(in) :: x                  !! fraction of the step
            real(dp) :: v
        end function dense_component_iface
    end interface

    !> Dense output of the last DOP853 step (7th order).
    type, extends(ode_dense_base) :: ode_dense_t
        real(dp), allocatable :: r(:, :)      !! coefficients r1..r7, n x 7
        real(dp), allocatable :: y0(:)        !! state at t0, n
    contains
        procedure :: value => dense_value
        procedure :: component => dense_component
    end type ode_dense_t

    !> DOP853 integrator state: tolerances and the stages of the last step.
    type :: ode_dop853_t
        integer :: n = 0                      !! state dimension
        real(dp) :: rtol = 1.0e-6_dp          !! relative tolerance
        real(dp), allocatable :: atol(:)      !! absolute tolerances, n
        real(dp), allocatable :: k(:, :)      !! stages, n2 x 16 (n2: n rounded up to even)
        real(dp), allocatable :: ys(:), yp(:) !! work, n2
        real(dp), allocatable :: w5(:), w3(:) !! work, n2
        type(ode_dense_t) :: dense            !! dense output of the last step (`dense_setup`)
    contains
        procedure :: init => dop853_init
        procedure :: step => dop853_step
        procedure :: dense_setup => dop853_dense
        procedure :: value => dop853_value
        procedure :: locate => dop853_locate
        procedure :: locate_event => dop853_locate_event
    end type ode_dop853_t

    !> Event function g_i(t, y) of a system on the dense output of a step (root finder).
    type, extends(scalar_function) :: event_fn
        class(ode_system), pointer :: sys => null()
        class(ode_dense_base), pointer :: dense => null()
        integer :: i = 0
        real(dp), allocatable :: y(:)
    contains
        procedure :: eval => event_eval
    end type event_fn

    ! Dormand & Prince 8(5,3) (DOP853) coefficients: Hairer's code, as in SciPy's
    ! dop853_coefficients.py (C, A incl. the 3 dense-output stages 14-16, B = A(13, :12),
    ! the 5th/3rd-order error weights E5/E3 and the dense-output matrix D).
    real(dp), parameter :: dop_c(16) = [ &
            0.0_dp, 0.05260015195876773_dp, 0.0789002279381516_dp, 0.1183503419072274_dp, &
            0.2816496580927726_dp, 0.3333333333333333_dp, 0.25_dp, 0.3076923076923077_dp, &
            0.6512820512820513_dp, 0.6_dp, 0.8571428571428571_dp, 1.0_dp, 1.0_dp, 0.1_dp, &
            0.2_dp, 0.7777777777777778_dp &
        ]
    real(dp), parameter :: dop_a(16, 16) = reshape([ &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.05260015195876773_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0197250569845379_dp, 0.0591751709536137_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.02958758547680685_dp, 0.0_dp, 0.08876275643042054_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.2413651341592667_dp, 0.0_dp, -0.8845494793282861_dp, 0.924834003261792_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, &
            0.037037037037037035_dp, 0.0_dp, 0.0_dp, 0.17082860872947386_dp, &
            0.12546768756682242_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.037109375_dp, 0.0_dp, 0.0_dp, 0.17025221101954405_dp, 0.06021653898045596_dp, &
            -0.017578125_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, &
            0.03709200011850479_dp, 0.0_dp, 0.0_dp, 0.17038392571223998_dp, &
            0.10726203044637328_dp, -0.015319437748624402_dp, 0.008273789163814023_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.6241109587160757_dp, 0.0_dp, 0.0_dp, -3.3608926294469414_dp, &
            -0.868219346841726_dp, 27.59209969944671_dp, 20.154067550477894_dp, &
            -43.48988418106996_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, &
            0.47766253643826434_dp, 0.0_dp, 0.0_dp, -2.4881146199716677_dp, &
            -0.590290826836843_dp, 21.230051448181193_dp, 15.279233632882423_dp, &
            -33.28821096898486_dp, -0.020331201708508627_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, &
            -0.9371424300859873_dp, 0.0_dp, 0.0_dp, 5.186372428844064_dp, 1.0914373489967295_dp, &
            -8.149787010746927_dp, -18.52006565999696_dp, 22.739487099350505_dp, &
            2.4936055526796523_dp, -3.0467644718982196_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, &
            2.273310147516538_dp, 0.0_dp, 0.0_dp, -10.53449546673725_dp, -2.0008720582248625_dp, &
            -17.9589318631188_dp, 27.94888452941996_dp, -2.8589982771350235_dp, &
            -8.87285693353063_dp, 12.360567175794303_dp, 0.6433927460157636_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, &
            0.054293734116568765_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 4.450312892752409_dp, &
            1.8915178993145003_dp, -5.801203960010585_dp, 0.3111643669578199_dp, &
            -0.1521609496625161_dp, 0.20136540080403034_dp, 0.04471061572777259_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, &
            0.056167502283047954_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.25350021021662483_dp, -0.2462390374708025_dp, -0.12419142326381637_dp, &
            0.15329179827876568_dp, 0.00820105229563469_dp, 0.007567897660545699_dp, &
            -0.008298_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.03183464816350214_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.028300909672366776_dp, &
            0.053541988307438566_dp, -0.05492374857139099_dp, 0.0_dp, 0.0_dp, &
            -0.00010834732869724932_dp, 0.0003825710908356584_dp, -0.00034046500868740456_dp, &
            0.1413124436746325_dp, 0.0_dp, 0.0_dp, &
            -0.42889630158379194_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, -4.697621415361164_dp, &
            7.683421196062599_dp, 4.06898981839711_dp, 0.3567271874552811_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, -0.0013990241651590145_dp, 2.9475147891527724_dp, -9.15095847217987_dp, &
            0.0_dp &
        ], [16, 16], order=[2, 1])
    real(dp), parameter :: dop_b(12) = [ &
            0.054293734116568765_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 4.450312892752409_dp, &
            1.8915178993145003_dp, -5.801203960010585_dp, 0.3111643669578199_dp, &
            -0.1521609496625161_dp, 0.20136540080403034_dp, 0.04471061572777259_dp &
        ]
    real(dp), parameter :: dop_e3(13) = [ &
            -0.18980075407240762_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 4.450312892752409_dp, &
            1.8915178993145003_dp, -5.801203960010585_dp, -0.4226823213237919_dp, &
            -0.1521609496625161_dp, 0.20136540080403034_dp, 0.02265179219836082_dp, 0.0_dp &
        ]
    real(dp), parameter :: dop_e5(13) = [ &
            0.01312004499419488_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, -1.2251564463762044_dp, &
            -0.4957589496572502_dp, 1.6643771824549864_dp, -0.35032884874997366_dp, &
            0.3341791187130175_dp, 0.08192320648511571_dp, -0.022355307863886294_dp, 0.0_dp &
        ]
    real(dp), parameter :: dop_d(4, 16) = reshape([ &
            -8.428938276109013_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.5667149535193777_dp, &
            -3.0689499459498917_dp, 2.38466765651207_dp, 2.117034582445028_dp, &
            -0.871391583777973_dp, 2.2404374302607883_dp, 0.6315787787694688_dp, &
            -0.08899033645133331_dp, 18.148505520854727_dp, -9.194632392478356_dp, &
            -4.436036387594894_dp, &
            10.427508642579134_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 242.28349177525817_dp, &
            165.20045171727028_dp, -374.5467547226902_dp, -22.113666853125306_dp, &
            7.733432668472264_dp, -30.674084731089398_dp, -9.332130526430229_dp, &
            15.697238121770845_dp, -31.139403219565178_dp, -9.35292435884448_dp, &
            35.81684148639408_dp, &
            19.985053242002433_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, -387.0373087493518_dp, &
            -189.17813819516758_dp, 527.8081592054236_dp, -11.57390253995963_dp, &
            6.8812326946963_dp, -1.0006050966910838_dp, 0.7777137798053443_dp, &
            -2.778205752353508_dp, -60.19669523126412_dp, 84.32040550667716_dp, &
            11.99229113618279_dp, &
            -25.69393346270375_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, -154.18974869023643_dp, &
            -231.5293791760455_dp, 357.6391179106141_dp, 93.40532418362432_dp, &
            -37.45832313645163_dp, 104.0996495089623_dp, 29.8402934266605_dp, &
            -43.53345659001114_dp, 96.32455395918828_dp, -39.17726167561544_dp, &
            -149.72683625798564_dp &
        ], [4, 16], order=[2, 1])

contains

    !> No events (the default of `ode_system%event`; a system with events overrides it
    !> with g_i(t, y), i = 1, 2, ...): 0 for any i.
    function ode_no_event(self, i, t, y) result(g)
        class(ode_system), intent(inout) :: self  !! the system
        integer, intent(in) :: i                  !! event number
        real(dp), intent(in) :: t                 !! time
        real(dp), intent(in) :: y(:)              !! state
        real(dp) :: g
        associate(unused => self, unused_i => i, unused_t => t, unused_y => y)
        end associate
        g = 0.0_dp
    end function ode_no_event

    !> Default Jacobian dfdy(i, j) = df_i/dy_j by forward differences, as RADAU5 [HW96]:
    !> column j from f(t, y + delta_j e_j), delta_j = sqrt(eps max(1e-5, |y_j|)), n right-hand
    !> sides. No allocation for n <= 32 (a local buffer holds the perturbed state).
    subroutine ode_fd_jacobian(self, t, y, f, dfdy)
        class(ode_system), intent(inout) :: self          !! the system
        real(dp), intent(in) :: t                         !! time
        real(dp), contiguous, intent(in) :: y(:)          !! state, n
        real(dp), contiguous, intent(in) :: f(:)          !! f(t, y), n
        real(dp), contiguous, intent(out) :: dfdy(:, :)   !! Jacobian, n x n
        integer, parameter :: n_local = 32
        real(dp) :: buf(n_local)
        real(dp), allocatable :: big(:)
        integer :: n
        n = size(y)
        if (n <= n_local) then
            call fd_columns(self, n, t, y, f, dfdy, buf(1:n))
        else
            allocate(big(n))
            call fd_columns(self, n, t, y, f, dfdy, big)
        end if
    end subroutine ode_fd_jacobian

    !> The n columns of `ode_fd_jacobian` with the perturbed state in yp.
    subroutine fd_columns(sys, n, t, y, f, dfdy, yp)
        class(ode_system), intent(inout) :: sys
        integer, intent(in) :: n
        real(dp), intent(in) :: t, y(n), f(n)
        real(dp), contiguous, intent(out) :: dfdy(:, :)
        real(dp), intent(inout) :: yp(n)
        real(dp) :: delta
        integer :: j
        yp = y
        do j = 1, n
            delta = sqrt(epsilon(1.0_dp) * max(1.0e-5_dp, abs(y(j))))
            yp(j) = y(j) + delta
            ! beyond |y_j| ~ 2e16 the increment is below half an ulp: take one ulp
            if (.not. (yp(j) > y(j))) yp(j) = nearest(y(j), 1.0_dp)
            delta = yp(j) - y(j)   ! the step actually taken (exact in floating point)
            call sys%rhs(t, yp, dfdy(:, j))
            dfdy(:, j) = (dfdy(:, j) - f) / delta
            yp(j) = y(j)
        end do
    end subroutine fd_columns

    !> Step-size factor after a step with error norm err (Hairer: 0.9 err^(-1/8)): at
    !> least 0.2 after a rejected step (err > 1, or NaN), at most 10 after an accepted
    !> one (10 for err = 0).
    pure function ode_dop853_factor(err) result(fac)
        real(dp), intent(in) :: err  !! error norm of the step, >= 0
        real(dp) :: fac
        if (.not. err <= 1.0_dp) then
            fac = max(0.2_dp, 0.9_dp * err**(-0.125_dp))
        else if (err > 0.0_dp) then
            fac = min(10.0_dp, 0.9_dp * err**(-0.125_dp))
        else
            fac = 10.0_dp
        end if
    end function ode_dop853_factor

    !> Set up for n states (allocates once; a second call with the same n reuses).
    subroutine dop853_init(self, n, rtol, atol, stat, errmsg)
        class(ode_dop853_t), intent(inout) :: self            !! the integrator
        integer, intent(in) :: n                              !! state dimension, >= 1
        real(dp), intent(in) :: rtol                          !! relative tolerance, > 0
        real(dp), intent(in) :: atol(:)                       !! absolute tolerances (n), >= 0
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: n2
        stat = SEISPULSE_SUCCESS
        if (n < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n: the state dimension ' &
                           //'must be >= 1')
            return
        else if (size(atol) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'atol: must have n elements')
            return
        else if (.not. in_open(rtol, 0.0_dp, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'rtol: must be in (0, 1)')
            return
        else if (.not. all(finite_at_least(atol, 0.0_dp))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'atol: must be finite and >= 0')
            return
        end if
        if (self%n /= n .or. .not. allocated(self%k)) then
            if (allocated(self%k)) deallocate(self%k, self%ys, self%yp, self%w5, self%w3, &
                                              self%atol, self%dense%r, self%dense%y0)
            n2 = n + mod(n, 2)
            allocate(self%k(n2, 16), self%ys(n2), self%yp(n2), self%w5(n2), self%w3(n2), &
                     self%atol(n), self%dense%r(n, 7), self%dense%y0(n))
            self%k = 0.0_dp
            self%ys = 0.0_dp
            self%yp = 0.0_dp
            self%dense%r = 0.0_dp
            self%dense%y0 = 0.0_dp
        end if
        self%n = n
        self%dense%n = n
        self%rtol = rtol
        self%atol(:) = atol
    end subroutine dop853_init

    !> One step of size h = t_new - t from (t, y), f = f(t, y): the 8th-order solution
    !> y_new, f_new = f(t_new, y_new) and the error norm err (<= 1: accept). The stages
    !> stay for `dense_setup`.
    subroutine dop853_step(self, sys, t, y, f, h, t_new, y_new, f_new, err)
        class(ode_dop853_t), intent(inout) :: self  !! the integrator (initialised)
        class(ode_system), intent(inout) :: sys     !! the system
        real(dp), intent(in) :: t                   !! start of the step
        real(dp), contiguous, intent(in) :: y(:)        !! state at t, n
        real(dp), contiguous, intent(in) :: f(:)        !! f(t, y), n
        real(dp), intent(in) :: h                   !! step size, t_new - t
        real(dp), intent(in) :: t_new               !! end of the step
        real(dp), contiguous, intent(out) :: y_new(:)    !! state at t_new, n
        real(dp), contiguous, intent(out) :: f_new(:)    !! f(t_new, y_new), n
        real(dp), intent(out) :: err                !! error norm
        call step_kernel(self%n, size(self%ys), sys, t, y, f, h, t_new, y_new, f_new, self%k, &
                         self%ys, self%yp, self%w5, self%w3, self%atol, self%rtol, err)
    end subroutine dop853_step

    !> `step` on explicit-shape arrays of n2 = n rounded up to even rows (the extra row,
    !> if any, stays 0). Each stage is one array expression on two components at a time
    !> (constant extent: one SIMD register), the sum in the order of j, the coefficients
    !> compile-time constants. Zero coefficients are left out (as in Hairer's code): a
    !> zero product leaves a finite sum unchanged, bit for bit, unless that sum is -0.
    subroutine step_kernel(n, n2, sys, t, y, f, h, t_new, y_new, f_new, k, ys, yp, w5, w3, &
                           atol, rtol, err)
        integer, intent(in) :: n, n2
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t, y(n), f(n), h, t_new, atol(n), rtol
        real(dp), intent(out) :: y_new(n), f_new(n), err
        real(dp), intent(inout) :: k(n2, 16), ys(n2), yp(n2), w5(n2), w3(n2)
        real(dp) :: n5, n3, e5, e3, sc
        integer :: m, mb
        ! copies two at a time (a library call per copy costs more for a few states)
        do m = 1, n - 1, 2
            mb = m + 1
            yp(m:mb) = y(m:mb)
            k(m:mb, 1) = f(m:mb)
        end do
        if (n < n2) then
            yp(n) = y(n)
            k(n, 1) = f(n)
        end if
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(2, 1)) * k(m:mb, 1)
        end do
        call sys%rhs(t + dop_c(2) * h, ys(1:n), k(1:n, 2))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(3, 1)) * k(m:mb, 1) &
                + (h * dop_a(3, 2)) * k(m:mb, 2)
        end do
        call sys%rhs(t + dop_c(3) * h, ys(1:n), k(1:n, 3))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(4, 1)) * k(m:mb, 1) &
                + (h * dop_a(4, 3)) * k(m:mb, 3)
        end do
        call sys%rhs(t + dop_c(4) * h, ys(1:n), k(1:n, 4))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(5, 1)) * k(m:mb, 1) &
                + (h * dop_a(5, 3)) * k(m:mb, 3) + (h * dop_a(5, 4)) * k(m:mb, 4)
        end do
        call sys%rhs(t + dop_c(5) * h, ys(1:n), k(1:n, 5))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(6, 1)) * k(m:mb, 1) &
                + (h * dop_a(6, 4)) * k(m:mb, 4) + (h * dop_a(6, 5)) * k(m:mb, 5)
        end do
        call sys%rhs(t + dop_c(6) * h, ys(1:n), k(1:n, 6))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(7, 1)) * k(m:mb, 1) &
                + (h * dop_a(7, 4)) * k(m:mb, 4) + (h * dop_a(7, 5)) * k(m:mb, 5) &
                + (h * dop_a(7, 6)) * k(m:mb, 6)
        end do
        call sys%rhs(t + dop_c(7) * h, ys(1:n), k(1:n, 7))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(8, 1)) * k(m:mb, 1) &
                + (h * dop_a(8, 4)) * k(m:mb, 4) + (h * dop_a(8, 5)) * k(m:mb, 5) &
                + (h * dop_a(8, 6)) * k(m:mb, 6) + (h * dop_a(8, 7)) * k(m:mb, 7)
        end do
        call sys%rhs(t + dop_c(8) * h, ys(1:n), k(1:n, 8))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(9, 1)) * k(m:mb, 1) &
                + (h * dop_a(9, 4)) * k(m:mb, 4) + (h * dop_a(9, 5)) * k(m:mb, 5) &
                + (h * dop_a(9, 6)) * k(m:mb, 6) + (h * dop_a(9, 7)) * k(m:mb, 7) &
                + (h * dop_a(9, 8)) * k(m:mb, 8)
        end do
        call sys%rhs(t + dop_c(9) * h, ys(1:n), k(1:n, 9))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(10, 1)) * k(m:mb, 1) &
                + (h * dop_a(10, 4)) * k(m:mb, 4) + (h * dop_a(10, 5)) * k(m:mb, 5) &
                + (h * dop_a(10, 6)) * k(m:mb, 6) + (h * dop_a(10, 7)) * k(m:mb, 7) &
                + (h * dop_a(10, 8)) * k(m:mb, 8) + (h * dop_a(10, 9)) * k(m:mb, 9)
        end do
        call sys%rhs(t + dop_c(10) * h, ys(1:n), k(1:n, 10))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(11, 1)) * k(m:mb, 1) &
                + (h * dop_a(11, 4)) * k(m:mb, 4) + (h * dop_a(11, 5)) * k(m:mb, 5) &
                + (h * dop_a(11, 6)) * k(m:mb, 6) + (h * dop_a(11, 7)) * k(m:mb, 7) &
                + (h * dop_a(11, 8)) * k(m:mb, 8) + (h * dop_a(11, 9)) * k(m:mb, 9) &
                + (h * dop_a(11, 10)) * k(m:mb, 10)
        end do
        call sys%rhs(t + dop_c(11) * h, ys(1:n), k(1:n, 11))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = yp(m:mb) + (h * dop_a(12, 1)) * k(m:mb, 1) &
                + (h * dop_a(12, 4)) * k(m:mb, 4) + (h * dop_a(12, 5)) * k(m:mb, 5) &
                + (h * dop_a(12, 6)) * k(m:mb, 6) + (h * dop_a(12, 7)) * k(m:mb, 7) &
                + (h * dop_a(12, 8)) * k(m:mb, 8) + (h * dop_a(12, 9)) * k(m:mb, 9) &
                + (h * dop_a(12, 10)) * k(m:mb, 10) + (h * dop_a(12, 11)) * k(m:mb, 11)
        end do
        call sys%rhs(t_new, ys(1:n), k(1:n, 12))
        do m = 1, n2, 2
            mb = m + 1
            ys(m:mb) = 0.0_dp + dop_b(1) * k(m:mb, 1) + dop_b(6) * k(m:mb, 6) &
                + dop_b(7) * k(m:mb, 7) + dop_b(8) * k(m:mb, 8) + dop_b(9) * k(m:mb, 9) &
                + dop_b(10) * k(m:mb, 10) + dop_b(11) * k(m:mb, 11) + dop_b(12) * k(m:mb, 12)
        end do
        y_new = y + h * ys(1:n)
        call sys%rhs(t_new, y_new, f_new)
        do m = 1, n - 1, 2
            mb = m + 1
            k(m:mb, 13) = f_new(m:mb)
        end do
        if (n < n2) k(n, 13) = f_new(n)
        do m = 1, n2, 2
            mb = m + 1
            w5(m:mb) = 0.0_dp + dop_e5(1) * k(m:mb, 1) + dop_e5(6) * k(m:mb, 6) &
                + dop_e5(7) * k(m:mb, 7) + dop_e5(8) * k(m:mb, 8) + dop_e5(9) * k(m:mb, 9) &
                + dop_e5(10) * k(m:mb, 10) + dop_e5(11) * k(m:mb, 11) + dop_e5(12) * k(m:mb, 12)
        end do
        do m = 1, n2, 2
            mb = m + 1
            w3(m:mb) = 0.0_dp + dop_e3(1) * k(m:mb, 1) + dop_e3(6) * k(m:mb, 6) &
                + dop_e3(7) * k(m:mb, 7) + dop_e3(8) * k(m:mb, 8) + dop_e3(9) * k(m:mb, 9) &
                + dop_e3(10) * k(m:mb, 10) + dop_e3(11) * k(m:mb, 11) + dop_e3(12) * k(m:mb, 12)
        end do
        n5 = 0.0_dp
        n3 = 0.0_dp
        do m = 1, n
            sc = atol(m) + rtol * max(abs(y(m)), abs(y_new(m)))
            e5 = w5(m) / sc
            e3 = w3(m) / sc
            n5 = n5 + e5**2
            n3 = n3 + e3**2
        end do
        if (n5 > 0.0_dp) then
            err = abs(h) * n5 / sqrt(real(n, dp) * (n5 + 0.01_dp * n3))
        else
            err = 0.0_dp
        end if
    end subroutine step_kernel

    !> `dense_setup` on explicit-shape arrays (as `step_kernel`).
    subroutine dense_kernel(n, n2, sys, t, y, f, h, y_new, f_new, k, ys, r)
        integer, intent(in) :: n, n2
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t, y(n), f(n), h, y_new(n), f_new(n)
        real(dp), intent(inout) :: k(n2, 16), ys(n2)
        real(dp), intent(out) :: r(n, 7)
        ys(:n) = y + (h * dop_a(14, 1)) * k(:n, 1) + (h * dop_a(14, 7)) * k(:n, 7) &
            + (h * dop_a(14, 8)) * k(:n, 8) + (h * dop_a(14, 9)) * k(:n, 9) &
            + (h * dop_a(14, 10)) * k(:n, 10) + (h * dop_a(14, 11)) * k(:n, 11) &
            + (h * dop_a(14, 12)) * k(:n, 12) + (h * dop_a(14, 13)) * k(:n, 13)
        call sys%rhs(t + dop_c(14) * h, ys(:n), k(:n, 14))
        ys(:n) = y + (h * dop_a(15, 1)) * k(:n, 1) + (h * dop_a(15, 6)) * k(:n, 6) &
            + (h * dop_a(15, 7)) * k(:n, 7) + (h * dop_a(15, 8)) * k(:n, 8) &
            + (h * dop_a(15, 11)) * k(:n, 11) + (h * dop_a(15, 12)) * k(:n, 12) &
            + (h * dop_a(15, 13)) * k(:n, 13) + (h * dop_a(15, 14)) * k(:n, 14)
        call sys%rhs(t + dop_c(15) * h, ys(:n), k(:n, 15))
        ys(:n) = y + (h * dop_a(16, 1)) * k(:n, 1) + (h * dop_a(16, 6)) * k(:n, 6) &
            + (h * dop_a(16, 7)) * k(:n, 7) + (h * dop_a(16, 8)) * k(:n, 8) &
            + (h * dop_a(16, 9)) * k(:n, 9) + (h * dop_a(16, 13)) * k(:n, 13) &
            + (h * dop_a(16, 14)) * k(:n, 14) + (h * dop_a(16, 15)) * k(:n, 15)
        call sys%rhs(t + dop_c(16) * h, ys(:n), k(:n, 16))
        r(:, 1) = y_new - y
        r(:, 2) = h * f - r(:, 1)
        r(:, 3) = 2.0_dp * r(:, 1) - h * (f_new + f)
        ys(:n) = 0.0_dp + dop_d(1, 1) * k(:n, 1) + dop_d(1, 6) * k(:n, 6) &
            + dop_d(1, 7) * k(:n, 7) + dop_d(1, 8) * k(:n, 8) + dop_d(1, 9) * k(:n, 9) &
            + dop_d(1, 10) * k(:n, 10) + dop_d(1, 11) * k(:n, 11) + dop_d(1, 12) * k(:n, 12) &
            + dop_d(1, 13) * k(:n, 13) + dop_d(1, 14) * k(:n, 14) + dop_d(1, 15) * k(:n, 15) &
            + dop_d(1, 16) * k(:n, 16)
        r(:, 4) = h * ys(:n)
        ys(:n) = 0.0_dp + dop_d(2, 1) * k(:n, 1) + dop_d(2, 6) * k(:n, 6) &
            + dop_d(2, 7) * k(:n, 7) + dop_d(2, 8) * k(:n, 8) + dop_d(2, 9) * k(:n, 9) &
            + dop_d(2, 10) * k(:n, 10) + dop_d(2, 11) * k(:n, 11) + dop_d(2, 12) * k(:n, 12) &
            + dop_d(2, 13) * k(:n, 13) + dop_d(2, 14) * k(:n, 14) + dop_d(2, 15) * k(:n, 15) &
            + dop_d(2, 16) * k(:n, 16)
        r(:, 5) = h * ys(:n)
        ys(:n) = 0.0_dp + dop_d(3, 1) * k(:n, 1) + dop_d(3, 6) * k(:n, 6) &
            + dop_d(3, 7) * k(:n, 7) + dop_d(3, 8) * k(:n, 8) + dop_d(3, 9) * k(:n, 9) &
            + dop_d(3, 10) * k(:n, 10) + dop_d(3, 11) * k(:n, 11) + dop_d(3, 12) * k(:n, 12) &
            + dop_d(3, 13) * k(:n, 13) + dop_d(3, 14) * k(:n, 14) + dop_d(3, 15) * k(:n, 15) &
            + dop_d(3, 16) * k(:n, 16)
        r(:, 6) = h * ys(:n)
        ys(:n) = 0.0_dp + dop_d(4, 1) * k(:n, 1) + dop_d(4, 6) * k(:n, 6) &
            + dop_d(4, 7) * k(:n, 7) + dop_d(4, 8) * k(:n, 8) + dop_d(4, 9) * k(:n, 9) &
            + dop_d(4, 10) * k(:n, 10) + dop_d(4, 11) * k(:n, 11) + dop_d(4, 12) * k(:n, 12) &
            + dop_d(4, 13) * k(:n, 13) + dop_d(4, 14) * k(:n, 14) + dop_d(4, 15) * k(:n, 15) &
            + dop_d(4, 16) * k(:n, 16)
        r(:, 7) = h * ys(:n)
    end subroutine dense_kernel

    !> The three extra stages and the coefficients of the 7th-order dense output of the
    !> step just taken by `step` (same arguments).
    subroutine dop853_dense(self, sys, t, y, f, h, y_new, f_new)
        class(ode_dop853_t), intent(inout) :: self  !! the integrator, after `step`
        class(ode_system), intent(inout) :: sys     !! the system
        real(dp), intent(in) :: t                   !! start of the step
        real(dp), contiguous, intent(in) :: y(:)        !! state at t, n
        real(dp), contiguous, intent(in) :: f(:)        !! f(t, y), n
        real(dp), intent(in) :: h                   !! step size
        real(dp), contiguous, intent(in) :: y_new(:)     !! state at t + h, n
        real(dp), contiguous, intent(in) :: f_new(:)     !! f there, n
        call dense_kernel(self%n, size(self%ys), sys, t, y, f, h, y_new, f_new, self%k, self%ys, &
                          self%dense%r)
        self%dense%y0 = y
        self%dense%t0 = t
        self%dense%h = h
    end subroutine dop853_dense

    !> Dense output y(t0 + x h) of the last step (after `dense_setup`).
    subroutine dop853_value(self, x, y)
        class(ode_dop853_t), intent(in) :: self  !! the integrator
        real(dp), intent(in) :: x                !! fraction of the step, [0, 1]
        real(dp), intent(out) :: y(:)            !! state, n
        call self%dense%value(x, y)
    end subroutine dop853_value

    !> Root x in [xa, xb] of sgn y(comp)(x) - level on the dense output, given its values
    !> fa, fb at the ends (of opposite signs, or one of them 0); x = xa if xb <= xa.
    subroutine dop853_locate(self, comp, sgn, level, xa, xb, fa, fb, x, stat, errmsg)
        class(ode_dop853_t), intent(inout) :: self            !! the integrator
        integer, intent(in) :: comp                           !! component, 1..n
        real(dp), intent(in) :: sgn                           !! its sign factor
        real(dp), intent(in) :: level                         !! level crossed
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: fa                            !! sgn y(comp) - level at xa
        real(dp), intent(in) :: fb                            !! same at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        call ode_locate(self%dense, comp, sgn, level, xa, xb, fa, fb, x, stat, errmsg)
    end subroutine dop853_locate

    !> Root x in [xa, xb] of the system's event function g_i(t0 + x h, y(x)) on the
    !> dense output, given ga, gb at the ends (of opposite signs, or one of them 0).
    subroutine dop853_locate_event(self, sys, i, xa, xb, ga, gb, x, stat, errmsg)
        class(ode_dop853_t), intent(inout), target :: self    !! the integrator
        class(ode_system), intent(inout), target :: sys       !! the system
        integer, intent(in) :: i                              !! event number
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: ga                            !! g_i at xa
        real(dp), intent(in) :: gb                            !! g_i at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        call ode_locate_event(self%dense, sys, i, xa, xb, ga, gb, x, stat, errmsg)
    end subroutine dop853_locate_event

    !> Root x in [xa, xb] of sgn y(comp)(x) - level on a dense output (any integrator's),
    !> given its values fa, fb at the ends (of opposite signs, or one of them 0); x = xa
    !> if xb <= xa.
    subroutine ode_locate(dense, comp, sgn, level, xa, xb, fa, fb, x, stat, errmsg)
        class(ode_dense_base), intent(inout) :: dense          !! dense output of a step
        integer, intent(in) :: comp                           !! component, 1..n
        real(dp), intent(in) :: sgn                           !! its sign factor
        real(dp), intent(in) :: level                         !! level crossed
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: fa                            !! sgn y(comp) - level at xa
        real(dp), intent(in) :: fb                            !! same at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (comp < 1 .or. comp > dense%n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'comp: must be in 1..n')
            x = xa
            return
        end if
        dense%comp = comp
        dense%sgn = sgn
        dense%level = level
        if (.not. xb > xa) then
            x = xa
            return
        end if
        call find_root(dense, xa, xb, x, stat, errmsg, fa_known=fa, fb_known=fb)
        if (stat /= SEISPULSE_SUCCESS) return
        x = min(max(x, xa), xb)
    end subroutine ode_locate

    !> Root x in [xa, xb] of the system's event function g_i(t0 + x h, y(x)) on a dense
    !> output (any integrator's), given ga, gb at the ends (of opposite signs, or one of
    !> them 0).
    subroutine ode_locate_event(dense, sys, i, xa, xb, ga, gb, x, stat, errmsg)
        class(ode_dense_base), intent(inout), target :: dense  !! dense output of a step
        class(ode_system), intent(inout), target :: sys       !! the system
        integer, intent(in) :: i                              !! event number
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: ga                            !! g_i at xa
        real(dp), intent(in) :: gb                            !! g_i at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(event_fn) :: ev
        stat = SEISPULSE_SUCCESS
        if (.not. xb > xa) then
            x = xa
            return
        end if
        ev%sys => sys
        ev%dense => dense
        ev%i = i
        allocate(ev%y(dense%n))
        call find_root(ev, xa, xb, x, stat, errmsg, fa_known=ga, fb_known=gb)
        if (stat /= SEISPULSE_SUCCESS) return
        x = min(max(x, xa), xb)
    end subroutine ode_locate_event

    !> y(t0 + x h) (Hairer's nested form).
    pure subroutine dense_value(self, x, y)
        class(ode_dense_t), intent(in) :: self  !! the dense output
        real(dp), intent(in) :: x               !! fraction of the step
        real(dp), intent(out) :: y(:)           !! state, n
        real(dp) :: xm
        xm = 1.0_dp - x
        y = self%r(:, 7) * x
        y = (y + self%r(:, 6)) * xm
        y = (y + self%r(:, 5)) * x
        y = (y + self%r(:, 4)) * xm
        y = (y + self%r(:, 3)) * x
        y = (y + self%r(:, 2)) * xm
        y = (y + self%r(:, 1)) * x
        y = y + self%y0
    end subroutine dense_value

    !> Component m of y(t0 + x h).
    pure function dense_component(self, m, x) result(v)
        class(ode_dense_t), intent(in) :: self  !! the dense output
        integer, intent(in) :: m                !! component, 1..n
        real(dp), intent(in) :: x               !! fraction of the step
        real(dp) :: v
        real(dp) :: xm
        xm = 1.0_dp - x
        v = self%r(m, 7) * x
        v = (v + self%r(m, 6)) * xm
        v = (v + self%r(m, 5)) * x
        v = (v + self%r(m, 4)) * xm
        v = (v + self%r(m, 3)) * x
        v = (v + self%r(m, 2)) * xm
        v = (v + self%r(m, 1)) * x
        v = v + self%y0(m)
    end function dense_component

    !> sgn y(comp)(t0 + x h) - level: the function `ode_locate` finds the roots of.
    function dense_eval(self, x) result(y)
        class(ode_dense_base), intent(inout) :: self  !! the dense output of one step
        real(dp), intent(in) :: x  !! fraction of the step (dimensionless), in [0, 1]
        real(dp) :: y
        y = self%sgn * self%component(self%comp, x) - self%level
    end function dense_eval

    function event_eval(self, x) result(g)
        class(event_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: g
        call self%dense%value(x, self%y)
        g = self%sys%event(self%i, self%dense%t0 + x * self%dense%h, self%y)
    end function event_eval

end module seispulse_ode
