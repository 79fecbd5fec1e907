!> Radau IIA integrator (seispulse_radau): a stiff linear system against its
!> eigendecomposition, the classical order 5, Van der Pol and Robertson against published
!> references, the collocation dense output, event location, the forward-difference
!> Jacobian, a Newton failure, the step-size factor and bad input.
module test_radau
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_ode, only: ode_system, ode_fd_jacobian
    use seispulse_radau, only: ode_radau5_t, ode_radau5_factor, radau5_solve
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_radau

    !> y' = A y, A = P B P^-1 with B = diag(-1e6, [-0.01 100; -100 -0.01]) (eigenvalues
    !> -1e6 and -0.01 +- 100 i) and P unit upper triangular; `exact` selects the
    !> Jacobian override (A) or the default forward differences.
    type, extends(ode_system) :: stiff_linear_t
        real(dp) :: a(3, 3) = 0.0_dp
        logical :: exact = .true.
        integer :: jac_calls = 0
    contains
        procedure :: rhs => stiff_linear_rhs
        procedure :: jacobian => stiff_linear_jacobian
    end type stiff_linear_t

    !> Logistic growth y' = y (1 - y) (y = 1/(1 + e^-t) from 1/2) and, as a second state,
    !> the harmonic oscillator y'' = -y split as (y2, y3).
    type, extends(ode_system) :: smooth_t
    contains
        procedure :: rhs => smooth_rhs
    end type smooth_t

    !> Van der Pol in Hairer's stiff scaling: y1' = y2, y2' = ((1 - y1^2) y2 - y1)/eps.
    type, extends(ode_system) :: vdpol_t
        real(dp) :: eps = 1.0e-6_dp
    contains
        procedure :: rhs => vdpol_rhs
        procedure :: jacobian => vdpol_jacobian
    end type vdpol_t

    !> Robertson's chemical kinetics (exact Jacobian when `exact`).
    type, extends(ode_system) :: robertson_t
        logical :: exact = .true.
    contains
        procedure :: rhs => robertson_rhs
        procedure :: jacobian => robertson_jacobian
    end type robertson_t

    !> Free flight y1' = y2, y2' = -g: y1 = v0 t - g t^2/2, zero at 2 v0/g (a cubic
    !> collocation polynomial is exact); event 1: y1; and y3' = -y3 (event 2: y3 - 1/2).
    type, extends(ode_system) :: flight_t
        real(dp) :: g = 9.81_dp
    contains
        procedure :: rhs => flight_rhs
        procedure :: event => flight_event
    end type flight_t

    !> y' = y^2 (blows up at t = 1/y0): no collocation solution for a long step.
    type, extends(ode_system) :: blowup_t
    contains
        procedure :: rhs => blowup_rhs
    end type blowup_t

    !> A switched system: y' = -1e6 y (in contact) or y' = 1 (free).
    type, extends(ode_system) :: switched_t
        logical :: contact = .true.
    contains
        procedure :: rhs => switched_rhs
    end type switched_t

    !> A pendulum with cubic damping, y1'' = -10 sin(y1) - 0.1 y1'^3 (nearly linear Newton
    !> phases, then a nonlinear one after a velocity jump); and f = (2 y1, y2).
    type, extends(ode_system) :: pendulum_t
    contains
        procedure :: rhs => pendulum_rhs
    end type pendulum_t

    !> f = (2 y1, y2).
    type, extends(ode_system) :: doubling_t
    contains
        procedure :: rhs => doubling_rhs
    end type doubling_t

contains

    subroutine collect_radau(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('stiff linear: eigenvalues -1e6, -0.01 +- 100 i', &
                              test_stiff_linear), &
                 new_unittest('classical order 5 with fixed steps', test_order), &
                 new_unittest('Van der Pol eps = 1e-6 (Hairer test set)', test_vdpol), &
                 new_unittest('Robertson at t = 40 and 1e11', test_robertson), &
                 new_unittest('dense output: collocation polynomial, order 4 inside', &
                              test_dense), &
                 new_unittest('event location on the dense output', test_events), &
                 new_unittest('forward-difference Jacobian', test_fd_jacobian), &
                 new_unittest('Newton failure: err = huge, no NaN', test_newton_failure), &
                 new_unittest('step-size factor', test_factor), &
                 new_unittest('bad input is a status', test_bad_input), &
                 new_unittest('restart: a switched system reuses nothing', test_restart), &
                 new_unittest('a new trajectory starts with a fresh contraction', &
                              test_new_trajectory), &
                 new_unittest('difference Jacobian beyond |y| = 2e16', test_fd_huge)]
    end subroutine collect_radau

    ! ---------------------------------------------------------------- systems

    subroutine stiff_linear_rhs(self, t, y, dydt)
        class(stiff_linear_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        dydt = matmul(self%a, y) + 0.0_dp * t
    end subroutine stiff_linear_rhs

    subroutine switched_rhs(self, t, y, dydt)
        class(switched_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        if (self%contact) then
            dydt = -1.0e6_dp * y + 0.0_dp * t
        else
            dydt = 1.0_dp
        end if
    end subroutine switched_rhs

    subroutine pendulum_rhs(self, t, y, dydt)
        class(pendulum_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        associate(unused => self)
        end associate
        dydt = [y(2), -10.0_dp * sin(y(1)) - 0.1_dp * y(2)**3 + 0.0_dp * t]
    end subroutine pendulum_rhs

    subroutine doubling_rhs(self, t, y, dydt)
        class(doubling_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        associate(unused => self)
        end associate
        dydt = [2.0_dp * y(1), y(2) + 0.0_dp * t]
    end subroutine doubling_rhs

    subroutine stiff_linear_jacobian(self, t, y, f, dfdy)
        class(stiff_linear_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(in) :: f(:)
        real(dp), contiguous, intent(out) :: dfdy(:, :)
        if (self%exact) then
            self%jac_calls = self%jac_calls + 1
            dfdy = self%a
        else
            call ode_fd_jacobian(self, t, y, f, dfdy)
        end if
    end subroutine stiff_linear_jacobian

    subroutine smooth_rhs(self, t, y, dydt)
        class(smooth_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        associate(unused => self)
        end associate
        dydt = [y(1) * (1.0_dp - y(1)), y(3), -y(2)] + 0.0_dp * t
    end subroutine smooth_rhs

    subroutine vdpol_rhs(self, t, y, dydt)
        class(vdpol_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        dydt = [y(2), ((1.0_dp - y(1)**2) * y(2) - y(1)) / self%eps] + 0.0_dp * t
    end subroutine vdpol_rhs

    subroutine vdpol_jacobian(self, t, y, f, dfdy)
        class(vdpol_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(in) :: f(:)
        real(dp), contiguous, intent(out) :: dfdy(:, :)
        associate(unused_t => t, unused_f => f)
        end associate
        dfdy(1, :) = [0.0_dp, 1.0_dp]
        dfdy(2, :) = [(-2.0_dp * y(1) * y(2) - 1.0_dp) / self%eps, &
                      (1.0_dp - y(1)**2) / self%eps]
    end subroutine vdpol_jacobian

    subroutine robertson_rhs(self, t, y, dydt)
        class(robertson_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        real(dp) :: r1, r2, r3
        associate(unused => self)
        end associate
        r1 = 0.04_dp * y(1)
        r2 = 1.0e4_dp * y(2) * y(3)
        r3 = 3.0e7_dp * y(2)**2
        dydt = [-r1 + r2, r1 - r2 - r3, r3] + 0.0_dp * t
    end subroutine robertson_rhs

    subroutine robertson_jacobian(self, t, y, f, dfdy)
        class(robertson_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(in) :: f(:)
        real(dp), contiguous, intent(out) :: dfdy(:, :)
        if (.not. self%exact) then
            call ode_fd_jacobian(self, t, y, f, dfdy)
            return
        end if
        dfdy = analytic_robertson(y)
    end subroutine robertson_jacobian

    pure function analytic_robertson(y) result(j)
        real(dp), intent(in) :: y(3)
        real(dp) :: j(3, 3)
        j(1, :) = [-0.04_dp, 1.0e4_dp * y(3), 1.0e4_dp * y(2)]
        j(2, :) = [0.04_dp, -1.0e4_dp * y(3) - 6.0e7_dp * y(2), -1.0e4_dp * y(2)]
        j(3, :) = [0.0_dp, 6.0e7_dp * y(2), 0.0_dp]
    end function analytic_robertson

    subroutine flight_rhs(self, t, y, dydt)
        class(flight_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        dydt = [y(2), -self%g, -y(3)] + 0.0_dp * t
    end subroutine flight_rhs

    function flight_event(self, i, t, y) result(g)
        class(flight_t), intent(inout) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp) :: g
        associate(unused => self, unused_t => t)
        end associate
        if (i == 1) then
            g = y(1)
        else
            g = y(3) - 0.5_dp
        end if
    end function flight_event

    subroutine blowup_rhs(self, t, y, dydt)
        class(blowup_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        associate(unused => self)
        end associate
        dydt = y**2 + 0.0_dp * t
    end subroutine blowup_rhs

    ! ---------------------------------------------------------------- helpers

    !> The stiff system's A = P B P^-1 and its exact solution P exp(B t) P^-1 y0, with
    !> P = [1 p12 p13; 0 1 p23; 0 0 1], P^-1 = [1 -p12 p12 p23 - p13; 0 1 -p23; 0 0 1].
    subroutine stiff_setup(a, t, y0, y)
        real(dp), intent(out) :: a(3, 3)
        real(dp), intent(in) :: t, y0(3)
        real(dp), intent(out) :: y(3)
        real(dp), parameter :: p12 = 0.5_dp, p13 = 0.25_dp, p23 = -0.75_dp
        real(dp), parameter :: lam = -1.0e6_dp, sig = -0.01_dp, om = 100.0_dp
        real(dp) :: p(3, 3), pinv(3, 3), b(3, 3), eb(3, 3)
        p = reshape([1.0_dp, 0.0_dp, 0.0_dp, p12, 1.0_dp, 0.0_dp, p13, p23, 1.0_dp], [3, 3])
        pinv = reshape([1.0_dp, 0.0_dp, 0.0_dp, -p12, 1.0_dp, 0.0_dp, p12 * p23 - p13, -p23, &
                        1.0_dp], [3, 3])
        b = 0.0_dp
        b(1, 1) = lam
        b(2, 2) = sig
        b(3, 3) = sig
        b(2, 3) = om
        b(3, 2) = -om
        a = matmul(p, matmul(b, pinv))
        ! exp(B t): e^(lam t) and e^(sig t) [cos om t, sin om t; -sin om t, cos om t]
        eb = 0.0_dp
        eb(1, 1) = exp(lam * t)
        eb(2, 2) = exp(sig * t) * cos(om * t)
        eb(3, 3) = eb(2, 2)
        eb(2, 3) = exp(sig * t) * sin(om * t)
        eb(3, 2) = -eb(2, 3)
        y = matmul(p, matmul(eb, matmul(pinv, y0)))
    end subroutine stiff_setup

    ! ---------------------------------------------------------------- tests

    !> y(1) from y0 = (1, 1, 1) for rtol = atol = 1e-6 and 1e-9: after 16 periods of the
    !> oscillation the error is within 50 rtol of the scale |y| ~ 1 (RADAU5's tolerance map
    !> makes it ~ rtol^(5/6): 8 rtol and 31 rtol here) and falls with rtol; with the exact
    !> and the difference Jacobian; a few
    !> hundred steps where an explicit method needs > 3e5 (h < 2.8/1e6).
    subroutine test_stiff_linear(error)
        type(test_error), allocatable, intent(out) :: error
        type(stiff_linear_t) :: sys
        real(dp) :: y(3), ex(3), y0(3), rtol, errs(2)
        integer :: stat, n_steps, k, mode
        y0 = [1.0_dp, 1.0_dp, 1.0_dp]
        call stiff_setup(sys%a, 1.0_dp, y0, ex)
        do mode = 1, 2
            sys%exact = mode == 1
            do k = 1, 2
                rtol = 10.0_dp**(-3 * k - 3)
                y = y0
                call radau5_solve(sys, 0.0_dp, 1.0_dp, y, rtol, [rtol], stat, n_steps=n_steps)
                call check(error, stat, SEISPULSE_SUCCESS, 'radau5_solve')
                if (allocated(error)) return
                errs(k) = maxval(abs(y - ex))
                call check(error, errs(k) <= 50.0_dp * rtol, 'error within 50 rtol')
                if (allocated(error)) return
                call check(error, n_steps < 3000, 'stiff: few steps')
                if (allocated(error)) return
            end do
            call check(error, errs(2) < 0.01_dp * errs(1), 'error falls with rtol')
            if (allocated(error)) return
        end do
        call check(error, sys%jac_calls > 0, 'the Jacobian override was used')
    end subroutine test_stiff_linear

    !> Fixed steps h = 0.25 and 0.125 over [0, 4] (logistic growth and cos/sin): the global
    !> error falls by 2^5 = 32 (ratio in [24, 40]); Newton converged far below it.
    subroutine test_order(error)
        type(test_error), allocatable, intent(out) :: error
        type(smooth_t) :: sys
        type(ode_radau5_t) :: ode
        real(dp) :: y(3), f(3), y_new(3), f_new(3), ex(3), t, h, err, e(2, 3)
        integer :: stat, j, k, nstep
        call ode%init(3, 1.0e-14_dp, [1.0e-14_dp, 1.0e-14_dp, 1.0e-14_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        ex = [1.0_dp / (1.0_dp + exp(-4.0_dp)), cos(4.0_dp), -sin(4.0_dp)]
        do j = 1, 2
            nstep = 16 * j
            h = 4.0_dp / real(nstep, dp)
            y = [0.5_dp, 1.0_dp, 0.0_dp]
            t = 0.0_dp
            call sys%rhs(t, y, f)
            do k = 1, nstep
                call ode%step(sys, t, y, f, h, real(k, dp) * h, y_new, f_new, err)
                call check(error, err < huge(1.0_dp), 'Newton converged')
                if (allocated(error)) return
                t = real(k, dp) * h
                y = y_new
                f = f_new
            end do
            e(j, :) = abs(y - ex)
        end do
        do k = 1, 3
            call check(error, e(1, k) / e(2, k) >= 24.0_dp .and. e(1, k) / e(2, k) <= 40.0_dp, &
                       'error ratio in [24, 40]')
            if (allocated(error)) return
        end do
        ! where Newton contracted fast the Jacobian was kept (RADAU5's theta test)
        call check(error, ode%n_jac < 16 + 32, 'Jacobian reused across steps')
    end subroutine test_order

    !> Hairer's test set, problem VDPOL (eps = 1e-6, y(0) = (2, 0)): reference values at
    !> t = 1 and 2 (E. Hairer, "Test set for stiff ODEs", unige.ch/~hairer/testset,
    !> stiff/vdpol/res_exact_pic): (-1.863646254808130, 0.7535430865435460),
    !> (1.706167732170456, -0.8928097010248257), here to 1e-10 with rtol 1e-12. RADAU5's
    !> example driver starts from y(0) = (2, -0.66), for which no reference is published:
    !> both initial values reach the slow manifold within a layer of O(eps), so their
    !> solutions differ by O(eps) (converged: 1.7e-7 and 3.5e-7 relative at t = 2); that
    !> run, at the driver's rtol 1e-6, is checked to 1e-5.
    subroutine test_vdpol(error)
        type(test_error), allocatable, intent(out) :: error
        type(vdpol_t) :: sys
        real(dp) :: y(2)
        integer :: stat, n_steps
        y = [2.0_dp, 0.0_dp]
        call radau5_solve(sys, 0.0_dp, 1.0_dp, y, 1.0e-12_dp, [1.0e-12_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'to t = 1')
        if (allocated(error)) return
        call check(error, y, [-1.863646254808130_dp, 0.7535430865435460_dp], rtol=1.0e-10_dp, &
                   message='y(1)')
        if (allocated(error)) return
        call radau5_solve(sys, 1.0_dp, 2.0_dp, y, 1.0e-12_dp, [1.0e-12_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'to t = 2')
        if (allocated(error)) return
        call check(error, y, [1.706167732170456_dp, -0.8928097010248257_dp], rtol=1.0e-10_dp, &
                   message='y(2)')
        if (allocated(error)) return
        ! RADAU5's own initial value, at the driver's tolerance
        y = [2.0_dp, -0.66_dp]
        call radau5_solve(sys, 0.0_dp, 2.0_dp, y, 1.0e-6_dp, [1.0e-6_dp], stat, n_steps=n_steps)
        call check(error, stat, SEISPULSE_SUCCESS, 'from (2, -0.66)')
        if (allocated(error)) return
        call check(error, y, [1.706167732170456_dp, -0.8928097010248257_dp], rtol=1.0e-5_dp, &
                   message='y(2) from (2, -0.66)')
        if (allocated(error)) return
        call check(error, n_steps < 1000, 'stiff: few steps')
    end subroutine test_vdpol

    !> Robertson from (1, 0, 0): at t = 40 the 7 digits of the example output of LSODE
    !> (Hindmarsh, ODEPACK; also SUNDIALS' cvRoberts_dns) (0.7158271, 9.185535e-6,
    !> 0.2841637); at t = 1e11 Hairer's test set, problem ROBER (unige.ch/~hairer/testset,
    !> stiff/rober): (0.2083340149701255e-7, 0.8333360770334713e-13, 0.9999999791665050).
    subroutine test_robertson(error)
        type(test_error), allocatable, intent(out) :: error
        type(robertson_t) :: sys
        real(dp) :: y(3)
        integer :: stat, n_steps, mode
        do mode = 1, 2
            sys%exact = mode == 1
            y = [1.0_dp, 0.0_dp, 0.0_dp]
            call radau5_solve(sys, 0.0_dp, 40.0_dp, y, 1.0e-10_dp, [1.0e-12_dp, 1.0e-16_dp, &
                              1.0e-12_dp], stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'to t = 40')
            if (allocated(error)) return
            ! within half a unit of the last printed digit
            call check(error, y(1), 0.7158271_dp, atol=5.0e-8_dp, message='y1(40)')
            if (allocated(error)) return
            call check(error, y(2), 9.185535e-6_dp, atol=5.0e-13_dp, message='y2(40)')
            if (allocated(error)) return
            call check(error, y(3), 0.2841637_dp, atol=5.0e-8_dp, message='y3(40)')
            if (allocated(error)) return
        end do
        sys%exact = .true.
        y = [1.0_dp, 0.0_dp, 0.0_dp]
        call radau5_solve(sys, 0.0_dp, 1.0e11_dp, y, 1.0e-10_dp, [1.0e-14_dp, 1.0e-20_dp, &
                          1.0e-14_dp], stat, n_steps=n_steps)
        call check(error, stat, SEISPULSE_SUCCESS, 'to t = 1e11')
        if (allocated(error)) return
        call check(error, y, [0.2083340149701255e-7_dp, 0.8333360770334713e-13_dp, &
                              0.9999999791665050_dp], rtol=1.0e-6_dp, message='y(1e11)')
        if (allocated(error)) return
        call check(error, n_steps < 2000, 'stiff: few steps')
    end subroutine test_robertson

    !> One step of h = 0.4 and 0.2 from exact data of (logistic, cos, -sin): the polynomial
    !> at x = 0.1..0.9 within 5e-5 (h = 0.4), its error falling by 2^4 = 16 (in [11, 22])
    !> for h/2, exact at both ends (x = 0: y, x = 1: y_new).
    subroutine test_dense(error)
        type(test_error), allocatable, intent(out) :: error
        type(smooth_t) :: sys
        type(ode_radau5_t) :: ode
        real(dp) :: y0(3), f0(3), y1(3), f1(3), err, h, x, yx(3), ex(3), worst(2), yh(3)
        integer :: stat, i, j
        call ode%init(3, 1.0e-10_dp, [1.0e-10_dp, 1.0e-10_dp, 1.0e-10_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        y0 = [0.5_dp, 1.0_dp, 0.0_dp]
        call sys%rhs(0.0_dp, y0, f0)
        worst = 0.0_dp
        do j = 1, 2
            h = 0.4_dp / real(j, dp)
            call ode%step(sys, 0.0_dp, y0, f0, h, h, y1, f1, err)
            call check(error, err < huge(1.0_dp), 'Newton converged')
            if (allocated(error)) return
            call ode%dense_setup(sys, 0.0_dp, y0, f0, h, y1, f1)
            do i = 1, 9
                x = 0.1_dp * real(i, dp)
                call ode%value(x, yx)
                ex = [1.0_dp / (1.0_dp + exp(-x * h)), cos(x * h), -sin(x * h)]
                worst(j) = max(worst(j), maxval(abs(yx - ex)))
            end do
            call ode%value(0.0_dp, yx)
            call check(error, yx, y0, rtol=0.0_dp, message='x = 0')
            if (allocated(error)) return
            call ode%value(1.0_dp, yx)
            call check(error, yx, y1, rtol=0.0_dp, message='x = 1')
            if (allocated(error)) return
            ! the Hermite fallback for a step that is not the last one (same order)
            if (j == 2) then
                call ode%dense_setup(sys, 0.0_dp, y0, f0, 0.4_dp, y0 + 1.0e-3_dp, f0)
                call ode%value(1.0_dp, yh)
                call check(error, yh, y0 + 1.0e-3_dp, rtol=0.0_dp, message='Hermite x = 1')
                if (allocated(error)) return
            end if
        end do
        call check(error, worst(1) < 5.0e-5_dp, 'inside the step, h = 0.4')
        if (allocated(error)) return
        call check(error, worst(1) / worst(2) >= 11.0_dp .and. worst(1) / worst(2) <= 22.0_dp, &
                   'error ratio ~ 16 for h/2')
    end subroutine test_dense

    !> Free flight from (0, 5): y1 = 0 at t = 10/9.81 (to 1e-12 relative, by `locate` on
    !> y1 and by `locate_event`); y3 = e^-t reaches 1/2 at ln 2 (to 1e-9 with rtol 1e-12).
    subroutine test_events(error)
        type(test_error), allocatable, intent(out) :: error
        type(flight_t) :: sys
        type(ode_radau5_t) :: ode
        real(dp) :: y(3), f(3), y_new(3), f_new(3), t, h, err, x, g0, g1, t_hit(3)
        integer :: stat, k, found
        call ode%init(3, 1.0e-12_dp, [1.0e-14_dp, 1.0e-14_dp, 1.0e-14_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        y = [0.0_dp, 5.0_dp, 1.0_dp]
        t = 0.0_dp
        h = 0.01_dp
        call sys%rhs(t, y, f)
        t_hit = -1.0_dp
        found = 0
        do k = 1, 10000
            call ode%step(sys, t, y, f, h, t + h, y_new, f_new, err)
            if (err <= 1.0_dp) then
                call ode%dense_setup(sys, t, y, f, h, y_new, f_new)
                if (t_hit(1) < 0.0_dp .and. y(1) > 0.0_dp .and. y_new(1) <= 0.0_dp &
                    .and. t > 0.0_dp) then
                    call ode%locate(1, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, y(1), y_new(1), x, stat)
                    call check(error, stat, SEISPULSE_SUCCESS, 'locate')
                    if (allocated(error)) return
                    t_hit(1) = t + x * h
                    g0 = sys%event(1, t, y)
                    g1 = sys%event(1, t + h, y_new)
                    call ode%locate_event(sys, 1, 0.0_dp, 1.0_dp, g0, g1, x, stat)
                    call check(error, stat, SEISPULSE_SUCCESS, 'locate_event 1')
                    if (allocated(error)) return
                    t_hit(2) = t + x * h
                    found = found + 1
                end if
                g0 = sys%event(2, t, y)
                g1 = sys%event(2, t + h, y_new)
                if (t_hit(3) < 0.0_dp .and. g0 > 0.0_dp .and. g1 <= 0.0_dp) then
                    call ode%locate_event(sys, 2, 0.0_dp, 1.0_dp, g0, g1, x, stat)
                    call check(error, stat, SEISPULSE_SUCCESS, 'locate_event 2')
                    if (allocated(error)) return
                    t_hit(3) = t + x * h
                    found = found + 1
                end if
                t = t + h
                y = y_new
                f = f_new
                if (found == 2) exit
            end if
            h = min(h * ode_radau5_factor(err, ode%newton_iters, ode%theta), 0.05_dp)
        end do
        call check(error, t_hit(1), 10.0_dp / 9.81_dp, rtol=1.0e-12_dp, message='locate')
        if (allocated(error)) return
        call check(error, t_hit(2), 10.0_dp / 9.81_dp, rtol=1.0e-12_dp, message='locate_event')
        if (allocated(error)) return
        call check(error, t_hit(3), log(2.0_dp), rtol=1.0e-9_dp, message='e^-t = 1/2')
    end subroutine test_events

    !> The default Jacobian against the analytic one: Robertson at a state with y2 ~ 1e-5
    !> (entries from 0.04 to 600), Van der Pol; within 1e-5 relative per entry.
    subroutine test_fd_jacobian(error)
        type(test_error), allocatable, intent(out) :: error
        type(robertson_t) :: rob
        type(vdpol_t) :: vdp
        real(dp) :: y(3), f(3), jfd(3, 3), jan(3, 3), y2(2), f2(2), jfd2(2, 2), jan2(2, 2)
        integer :: i
        rob%exact = .false.
        y = [0.7_dp, 1.2e-5_dp, 0.3_dp]
        call rob%rhs(0.0_dp, y, f)
        call rob%jacobian(0.0_dp, y, f, jfd)
        jan = analytic_robertson(y)
        do i = 1, 3
            call check(error, jfd(i, :), jan(i, :), rtol=1.0e-5_dp, atol=1.0e-12_dp, &
                       message='Robertson row')
            if (allocated(error)) return
        end do
        y2 = [1.5_dp, -0.7_dp]
        call vdp%rhs(0.0_dp, y2, f2)
        call ode_fd_jacobian(vdp, 0.0_dp, y2, f2, jfd2)
        call vdp%jacobian(0.0_dp, y2, f2, jan2)
        do i = 1, 2
            call check(error, jfd2(i, :), jan2(i, :), rtol=1.0e-5_dp, atol=1.0e-9_dp, &
                       message='Van der Pol row')
            if (allocated(error)) return
        end do
    end subroutine test_fd_jacobian

    !> A step far too long for Newton: y' = y^2 from 1 with h = 10 (no collocation
    !> solution near y), Van der Pol from (2, 0) with h = 1 (across the jump at t = 0.8):
    !> err = huge, y_new = y and
    !> f_new = f (finite), the factor 0.5; the halved steps then succeed.
    subroutine test_newton_failure(error)
        type(test_error), allocatable, intent(out) :: error
        type(blowup_t) :: sys
        type(vdpol_t) :: vdp
        type(ode_radau5_t) :: ode, ode2
        real(dp) :: y(1), f(1), y_new(1), f_new(1), err, h, yv(2), fv(2), yv_new(2), fv_new(2)
        integer :: stat, k
        call ode%init(1, 1.0e-6_dp, [1.0e-6_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        y = [1.0_dp]
        call sys%rhs(0.0_dp, y, f)
        h = 10.0_dp
        call ode%step(sys, 0.0_dp, y, f, h, h, y_new, f_new, err)
        call check(error, err >= huge(1.0_dp), 'err = huge')
        if (allocated(error)) return
        call check(error, y_new, y, rtol=0.0_dp, message='y_new = y')
        if (allocated(error)) return
        call check(error, f_new, f, rtol=0.0_dp, message='f_new = f')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(err, ode%newton_iters), 0.5_dp, message='factor')
        if (allocated(error)) return
        do k = 1, 60
            h = 0.5_dp * h
            call ode%step(sys, 0.0_dp, y, f, h, h, y_new, f_new, err)
            if (err < huge(1.0_dp)) exit
        end do
        call check(error, err < huge(1.0_dp), 'a shorter step converges')
        if (allocated(error)) return
        call check(error, h < 1.0_dp, 'only a step short of the blow-up at t = 1')
        if (allocated(error)) return
        call ode2%init(2, 1.0e-6_dp, [1.0e-6_dp, 1.0e-6_dp], stat)
        yv = [2.0_dp, 0.0_dp]
        call vdp%rhs(0.0_dp, yv, fv)
        call ode2%step(vdp, 0.0_dp, yv, fv, 1.0_dp, 1.0_dp, yv_new, fv_new, err)
        call check(error, err >= huge(1.0_dp), 'Van der Pol: err = huge')
        if (allocated(error)) return
        call check(error, all(abs(fv_new) < huge(1.0_dp)), 'Van der Pol: f_new finite')
    end subroutine test_newton_failure

    !> RADAU5's factor: 0.9 err^(-1/4) for one Newton iteration, smaller for more, within
    !> [0.2, 8]; 1 in the band [1, 1.2] when theta <= 0.001; 0.5 after a Newton failure.
    subroutine test_factor(error)
        type(test_error), allocatable, intent(out) :: error
        call check(error, ode_radau5_factor(1.0_dp, 1), 0.9_dp, message='err = 1')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(1.0e-10_dp, 1), 8.0_dp, message='max')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(1.0e10_dp, 1), 0.2_dp, message='min')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(0.5_dp, 1, 1.0e-4_dp), 1.0_dp, message='keep h')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(0.5_dp, 1), 0.9_dp * 0.5_dp**(-0.25_dp), &
                   message='no theta: no band')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(0.5_dp, 1, 0.01_dp), 0.9_dp * 0.5_dp**(-0.25_dp), &
                   message='theta > 0.001: no band')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(2.0_dp, 7), 0.9_dp * 15.0_dp / 21.0_dp &
                   * 2.0_dp**(-0.25_dp), message='7 iterations')
        if (allocated(error)) return
        call check(error, ode_radau5_factor(huge(1.0_dp), 3), 0.5_dp, message='failure')
    end subroutine test_factor

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(ode_radau5_t) :: ode
        type(vdpol_t) :: vdp
        real(dp) :: y(2)
        integer :: stat
        character(len=200) :: msg
        call ode%init(2, 1.0e-6_dp, [1.0e-6_dp, 0.0_dp], stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'atol = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'atol') == 1, 'message names atol')
        if (allocated(error)) return
        call ode%init(2, 0.0_dp, [1.0e-6_dp, 1.0e-6_dp], stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'rtol = 0')
        if (allocated(error)) return
        call ode%init(0, 1.0e-6_dp, [real(dp) ::], stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'n = 0')
        if (allocated(error)) return
        y = [2.0_dp, 0.0_dp]
        call radau5_solve(vdp, 0.0_dp, 1.0_dp, y, 1.0e-6_dp, [1.0_dp, 1.0_dp, 1.0_dp], stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'atol of 3 for n = 2')
        if (allocated(error)) return
        ! a subnormal atol whose mapped value rtol' atol/rtol underflows to 0
        call ode%init(2, 1.0e-6_dp, [1.0e-320_dp, 1.0e-6_dp], stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'atol mapped to 0')
    end subroutine test_bad_input

    !> The free system y' = 1 after a contact phase, from the same (t, y): after `restart`
    !> the step is exact (y + h); without it the stale contact Jacobian would be kept and
    !> the step accepted about 1e-6 long instead of 0.1.
    subroutine test_restart(error)
        type(test_error), allocatable, intent(out) :: error
        type(switched_t) :: sys
        type(ode_radau5_t) :: ode
        real(dp) :: y(1), f(1), y_new(1), f_new(1), err, t, h
        integer :: stat
        call ode%init(1, 1.0e-6_dp, [1.0e-6_dp], stat)
        t = 0.0_dp
        y = [1.0_dp]
        call sys%rhs(t, y, f)
        h = 1.0e-7_dp
        call ode%step(sys, t, y, f, h, t + h, y_new, f_new, err)
        call check(error, err <= 1.0_dp, 'contact step accepted')
        if (allocated(error)) return
        ! a rejected attempt from the same state leaves the contact Jacobian "exact" there
        call ode%step(sys, t, y, f, 1.0_dp, 1.0_dp, y_new, f_new, err)
        sys%contact = .false.
        call sys%rhs(t, y, f)
        call ode%restart()
        h = 0.1_dp
        call ode%step(sys, t, y, f, h, t + h, y_new, f_new, err)
        call check(error, err <= 1.0_dp, 'free step accepted')
        if (allocated(error)) return
        call check(error, y_new(1), y(1) + h, rtol=1.0e-12_dp, message='y + h')
    end subroutine test_restart

    !> After a velocity jump (an impact) the step must not inherit the fast Newton
    !> contraction of a nearly linear phase: the same step as a fresh integrator's, bit for
    !> bit (with the inherited contraction one unconverged iteration passed, 1e-2 wrong).
    subroutine test_new_trajectory(error)
        type(test_error), allocatable, intent(out) :: error
        type(pendulum_t) :: sys
        type(ode_radau5_t) :: ode, fresh
        real(dp) :: t, y(2), f(2), h, y_new(2), f_new(2), err, y2(2), f2(2), err2, yj(2)
        integer :: stat, i
        call ode%init(2, 1.0e-6_dp, [1.0e-6_dp, 1.0e-6_dp], stat)
        call fresh%init(2, 1.0e-6_dp, [1.0e-6_dp, 1.0e-6_dp], stat)
        t = 0.0_dp
        y = [1.0_dp, 0.0_dp]
        h = 1.0e-3_dp
        call sys%rhs(t, y, f)
        do i = 1, 100000
            call ode%step(sys, t, y, f, h, t + h, y_new, f_new, err)
            if (err <= 1.0_dp) then
                t = t + h
                y = y_new
                f = f_new
            end if
            h = h * ode_radau5_factor(err, ode%newton_iters, ode%theta)
            if (t > 3.0_dp) exit
        end do
        ode%faccon = 1.0e-9_dp   ! the history of a nearly linear, fast-contracting phase
        yj = [y(1), -0.8_dp * y(2)]
        call sys%rhs(t, yj, f)
        call ode%step(sys, t, yj, f, h, t + h, y_new, f_new, err)
        call fresh%step(sys, t, yj, f, h, t + h, y2, f2, err2)
        call check(error, ode%newton_iters, fresh%newton_iters, 'Newton iterations')
        if (allocated(error)) return
        call check(error, err, err2, rtol=0.0_dp, message='err')
        if (allocated(error)) return
        call check(error, y_new, y2, rtol=0.0_dp, message='y_new')
    end subroutine test_new_trajectory

    !> Beyond |y_j| ~ 2e16 sqrt(eps |y_j|) is below half an ulp: the difference step is
    !> one ulp, never 0 (0/0). f = (2 y1, y2): df1/dy1 = 2 exactly.
    subroutine test_fd_huge(error)
        type(test_error), allocatable, intent(out) :: error
        type(doubling_t) :: sys
        real(dp) :: y(2), f(2), dfdy(2, 2)
        y = [1.0e17_dp, 1.0_dp]
        call sys%rhs(0.0_dp, y, f)
        call ode_fd_jacobian(sys, 0.0_dp, y, f, dfdy)
        call check(error, dfdy(1, 1), 2.0_dp, rtol=0.0_dp, message='df1/dy1')
        if (allocated(error)) return
        call check(error, dfdy(2, 2), 1.0_dp, rtol=1.0e-7_dp, message='df2/dy2')
    end subroutine test_fd_huge

end module test_radau
