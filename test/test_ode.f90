!> DOP853 integrator (seispulse_ode): exact solutions of linear systems of 1, 2 and 3
!> states, dense output between steps, event location, error against the tolerance,
!> the step-size factor and bad input.
module test_ode
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_ode, only: ode_system, ode_dop853_t, ode_dop853_factor
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_ode

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp

    !> y'' = -w^2 y as (y, y'); event 1: y - 1/2, event 2: y'.
    type, extends(ode_system) :: oscillator_t
        real(dp) :: w = 1.0_dp
        integer :: calls = 0
    contains
        procedure :: rhs => oscillator_rhs
        procedure :: event => oscillator_event
    end type oscillator_t

    !> y' = -lam y (one state).
    type, extends(ode_system) :: decay_t
        real(dp) :: lam = 1.0_dp
    contains
        procedure :: rhs => decay_rhs
    end type decay_t

    !> y' = A y, A = -I + N with N the 3 x 3 upper shift: exp(A t) = e^-t (I + N t + N^2 t^2/2).
    type, extends(ode_system) :: jordan_t
    contains
        procedure :: rhs => jordan_rhs
    end type jordan_t

contains

    subroutine collect_ode(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('harmonic oscillator: cos, sin over 5 periods', test_oscillator), &
                 new_unittest('exponential decay (one state)', test_decay), &
                 new_unittest('3-state Jordan block: matrix exponential', test_jordan), &
                 new_unittest('dense output between steps, ends exact', test_dense), &
                 new_unittest('event location: y = 0 at pi/2, y = 1/2 at pi/3', test_events), &
                 new_unittest('error follows the tolerance', test_tolerance), &
                 new_unittest('step-size factor', test_factor), &
                 new_unittest('bad input is a status', test_bad_input)]
    end subroutine collect_ode

    ! ---------------------------------------------------------------- systems

    subroutine oscillator_rhs(self, t, y, dydt)
        class(oscillator_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        self%calls = self%calls + 1
        dydt(1) = y(2) + 0.0_dp * t
        dydt(2) = -self%w**2 * y(1)
    end subroutine oscillator_rhs

    function oscillator_event(self, i, t, y) result(g)
        class(oscillator_t), intent(inout) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: t
        real(dp), intent(in) :: y(:)
        real(dp) :: g
        if (i == 1) then
            g = y(1) - 0.5_dp + 0.0_dp * t * self%w
        else
            g = y(2)
        end if
    end function oscillator_event

    subroutine decay_rhs(self, t, y, dydt)
        class(decay_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        dydt(1) = -self%lam * y(1) + 0.0_dp * t
    end subroutine decay_rhs

    subroutine jordan_rhs(self, t, y, dydt)
        class(jordan_t), intent(inout) :: self
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:)
        real(dp), contiguous, intent(out) :: dydt(:)
        associate(unused => self)
        end associate
        dydt(1) = -y(1) + y(2) + 0.0_dp * t
        dydt(2) = -y(2) + y(3)
        dydt(3) = -y(3)
    end subroutine jordan_rhs

    ! ---------------------------------------------------------------- helpers

    !> Adaptive integration from (0, y0) to t_end (Hairer's factor, last step clamped).
    subroutine integrate(sys, y0, t_end, rtol, atol, y, n_steps, error)
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: y0(:), t_end, rtol, atol
        real(dp), intent(out) :: y(:)
        integer, intent(out) :: n_steps
        type(test_error), allocatable, intent(inout) :: error
        type(ode_dop853_t) :: ode
        real(dp) :: t, h, hh, t_new, err, f(size(y0)), y_new(size(y0)), f_new(size(y0))
        integer :: stat, k
        call ode%init(size(y0), rtol, [(atol, k = 1, size(y0))], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        t = 0.0_dp
        y = y0
        call sys%rhs(t, y, f)
        h = 1.0e-3_dp
        n_steps = 0
        do k = 1, 100000
            if (.not. t < t_end) exit
            t_new = min(t + h, t_end)
            hh = t_new - t
            call ode%step(sys, t, y, f, hh, t_new, y_new, f_new, err)
            n_steps = n_steps + 1
            if (err <= 1.0_dp) then
                t = t_new
                y = y_new
                f = f_new
            end if
            h = hh * ode_dop853_factor(err)
        end do
        call check(error, t >= t_end, 'integration reached t_end')
    end subroutine integrate

    ! ---------------------------------------------------------------- tests

    subroutine test_oscillator(error)
        type(test_error), allocatable, intent(out) :: error
        type(oscillator_t) :: sys
        real(dp) :: y(2), t_end
        integer :: n_steps
        sys%w = 2.0_dp
        t_end = 5.0_dp * pi     ! 5 periods of 2 pi/w
        call integrate(sys, [1.0_dp, 0.0_dp], t_end, 1.0e-11_dp, 1.0e-13_dp, y, n_steps, error)
        if (allocated(error)) return
        call check(error, y(1), cos(sys%w * t_end), atol=1.0e-9_dp, message='y = cos w t')
        if (allocated(error)) return
        call check(error, y(2), -sys%w * sin(sys%w * t_end), atol=2.0e-9_dp, &
                   message="y' = -w sin w t")
        if (allocated(error)) return
        ! 12 stages per step, plus f(t_new) (the 13th is f at the next step's start)
        call check(error, sys%calls, 12 * n_steps + 1, 'right-hand side calls')
    end subroutine test_oscillator

    subroutine test_decay(error)
        type(test_error), allocatable, intent(out) :: error
        type(decay_t) :: sys
        real(dp) :: y(1)
        integer :: n_steps
        sys%lam = 3.0_dp
        call integrate(sys, [2.0_dp], 4.0_dp, 1.0e-12_dp, 1.0e-14_dp, y, n_steps, error)
        if (allocated(error)) return
        call check(error, y(1), 2.0_dp * exp(-12.0_dp), rtol=1.0e-9_dp, message='2 e^(-3 t)')
    end subroutine test_decay

    subroutine test_jordan(error)
        type(test_error), allocatable, intent(out) :: error
        type(jordan_t) :: sys
        real(dp) :: y(3), y0(3), ex(3), t
        integer :: n_steps
        y0 = [0.5_dp, -1.0_dp, 2.0_dp]
        t = 3.0_dp
        call integrate(sys, y0, t, 1.0e-12_dp, 1.0e-14_dp, y, n_steps, error)
        if (allocated(error)) return
        ! e^(At) y0 = e^-t [y1 + t y2 + t^2/2 y3, y2 + t y3, y3]
        ex = exp(-t) * [y0(1) + t * y0(2) + 0.5_dp * t**2 * y0(3), y0(2) + t * y0(3), y0(3)]
        call check(error, y, ex, rtol=1.0e-9_dp, atol=1.0e-13_dp, message='exp(A t) y0')
    end subroutine test_jordan

    !> One step of h = 0.4 and of 0.2 from (1, 0) of cos 2t: the dense output inside the
    !> step within 1e-6 (h = 0.4; linear interpolation: ~7e-2), its error falling as h^8
    !> (7th order: > 100 times for h/2, 256 asymptotically), exact at both ends.
    subroutine test_dense(error)
        type(test_error), allocatable, intent(out) :: error
        type(oscillator_t) :: sys
        type(ode_dop853_t) :: ode
        real(dp) :: y0(2), f0(2), y1(2), f1(2), err, h, x, yx(2), ex(2), lin(2), worst(2)
        real(dp) :: worst_lin
        integer :: stat, i, j
        sys%w = 2.0_dp
        call ode%init(2, 1.0e-10_dp, [1.0e-12_dp, 1.0e-12_dp], stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'init')
        if (allocated(error)) return
        y0 = [1.0_dp, 0.0_dp]
        call sys%rhs(0.0_dp, y0, f0)
        worst = 0.0_dp
        worst_lin = 0.0_dp
        do j = 1, 2
            h = 0.4_dp / real(j, dp)
            call ode%step(sys, 0.0_dp, y0, f0, h, h, y1, f1, err)
            call ode%dense_setup(sys, 0.0_dp, y0, f0, h, y1, f1)
            do i = 1, 9
                x = 0.1_dp * real(i, dp)
                call ode%value(x, yx)
                ex = [cos(2.0_dp * x * h), -2.0_dp * sin(2.0_dp * x * h)]
                worst(j) = max(worst(j), maxval(abs(yx - ex)))
                if (j == 1) then
                    lin = (1.0_dp - x) * y0 + x * y1
                    worst_lin = max(worst_lin, maxval(abs(lin - ex)))
                end if
            end do
        end do
        call check(error, worst(1) < 1.0e-6_dp, 'dense output within 1e-6 of cos, sin')
        if (allocated(error)) return
        call check(error, worst_lin > 1.0e-2_dp, 'linear interpolation is far worse')
        if (allocated(error)) return
        call check(error, worst(1) / worst(2) > 100.0_dp, 'error ~ h^8')
        if (allocated(error)) return
        ! the last step (h = 0.2): ends
        call ode%value(0.0_dp, yx)
        call check(error, yx, y0, rtol=0.0_dp, message='x = 0: y0')
        if (allocated(error)) return
        call ode%value(1.0_dp, yx)
        call check(error, yx, y1, rtol=1.0e-15_dp, atol=1.0e-16_dp, message='x = 1: y_new')
        if (allocated(error)) return
        call check(error, ode%dense%component(2, 0.5_dp), -2.0_dp * sin(0.2_dp), &
                   atol=1.0e-8_dp, message='one component')
    end subroutine test_dense

    !> cos t from 0: steps until y changes sign; locate y = 0 (component form) and the
    !> system's event y = 1/2 (event function), both to 1e-10.
    subroutine test_events(error)
        type(test_error), allocatable, intent(out) :: error
        type(oscillator_t) :: sys
        type(ode_dop853_t) :: ode
        real(dp) :: t, h, y(2), f(2), y1(2), f1(2), err, x, ga, gb
        integer :: stat, k
        logical :: half_done
        call ode%init(2, 1.0e-10_dp, [1.0e-12_dp, 1.0e-12_dp], stat)
        t = 0.0_dp
        y = [1.0_dp, 0.0_dp]
        h = 0.3_dp
        call sys%rhs(t, y, f)
        half_done = .false.
        do k = 1, 100
            call ode%step(sys, t, y, f, h, t + h, y1, f1, err)
            call check(error, err <= 1.0_dp, 'steps of 0.3 accepted at rtol 1e-10')
            if (allocated(error)) return
            call ode%dense_setup(sys, t, y, f, h, y1, f1)
            if (.not. half_done .and. y1(1) <= 0.5_dp) then
                ga = sys%event(1, t, y)
                gb = sys%event(1, t + h, y1)
                call ode%locate_event(sys, 1, 0.0_dp, 1.0_dp, ga, gb, x, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'locate_event')
                if (allocated(error)) return
                call check(error, t + x * h, pi / 3.0_dp, rtol=1.0e-10_dp, &
                           message='cos t = 1/2 at pi/3')
                if (allocated(error)) return
                half_done = .true.
            end if
            if (y1(1) <= 0.0_dp) then
                call ode%locate(1, -1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, -y(1), -y1(1), x, stat)
                call check(error, stat, SEISPULSE_SUCCESS, 'locate')
                if (allocated(error)) return
                call check(error, half_done, 'the y = 1/2 event came first')
                if (allocated(error)) return
                call check(error, t + x * h, 0.5_dp * pi, rtol=1.0e-10_dp, &
                           message='cos t = 0 at pi/2')
                return
            end if
            t = t + h
            y = y1
            f = f1
        end do
        call check(error, .false., 'no crossing found')
    end subroutine test_events

    !> Global error of the oscillator over 3 periods for rtol = 1e-5, 1e-7, 1e-9, 1e-11:
    !> below 100 rtol and falling with it; more steps for smaller rtol, about
    !> rtol^(-1/8) (8th order): between 1.3 and 2.5 times per factor 100.
    subroutine test_tolerance(error)
        type(test_error), allocatable, intent(out) :: error
        type(oscillator_t) :: sys
        real(dp) :: y(2), rtol, e(4), t_end
        integer :: n(4), k
        t_end = 6.0_dp * pi
        do k = 1, 4
            rtol = 10.0_dp**(-3 - 2 * k)
            sys%calls = 0
            call integrate(sys, [1.0_dp, 0.0_dp], t_end, rtol, rtol, y, n(k), error)
            if (allocated(error)) return
            e(k) = max(abs(y(1) - cos(t_end)), abs(y(2) + sin(t_end)))
            call check(error, e(k) < 100.0_dp * rtol, 'error below 100 rtol')
            if (allocated(error)) return
        end do
        call check(error, all(e(2:4) < e(1:3)), 'error falls with rtol')
        if (allocated(error)) return
        call check(error, e(1) / e(4) > 1.0e3_dp, 'six decades of rtol: > 3 decades of error')
        if (allocated(error)) return
        do k = 1, 3
            call check(error, real(n(k + 1), dp) / real(n(k), dp) > 1.3_dp .and. &
                       real(n(k + 1), dp) / real(n(k), dp) < 2.5_dp, 'steps ~ rtol^(-1/8)')
            if (allocated(error)) return
        end do
    end subroutine test_tolerance

    subroutine test_factor(error)
        type(test_error), allocatable, intent(out) :: error
        call check(error, ode_dop853_factor(0.0_dp), 10.0_dp, message='err = 0: 10')
        if (allocated(error)) return
        call check(error, ode_dop853_factor(1.0_dp), 0.9_dp, message='err = 1: 0.9')
        if (allocated(error)) return
        call check(error, ode_dop853_factor(2.0_dp**(-8)), 1.8_dp, message='err = 2^-8: 1.8')
        if (allocated(error)) return
        call check(error, ode_dop853_factor(1.0e-12_dp), 10.0_dp, message='tiny err: 10')
        if (allocated(error)) return
        call check(error, ode_dop853_factor(2.0_dp**8), 0.45_dp, message='err = 2^8: 0.45')
        if (allocated(error)) return
        call check(error, ode_dop853_factor(1.0e12_dp), 0.2_dp, message='huge err: 0.2')
    end subroutine test_factor

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(ode_dop853_t) :: ode
        integer :: stat
        character(len=100) :: msg
        real(dp) :: x
        msg = ''
        call ode%init(0, 1.0e-6_dp, [real(dp) ::], stat, msg)
        call expect('n')
        if (allocated(error)) return
        call ode%init(2, 1.0e-6_dp, [1.0_dp], stat, msg)
        call expect('atol')
        if (allocated(error)) return
        call ode%init(2, 0.0_dp, [1.0_dp, 1.0_dp], stat, msg)
        call expect('rtol')
        if (allocated(error)) return
        call ode%init(2, 1.0e-6_dp, [1.0_dp, -1.0_dp], stat, msg)
        call expect('atol')
        if (allocated(error)) return
        call ode%init(2, 1.0e-6_dp, [1.0_dp, 1.0_dp], stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'valid init')
        if (allocated(error)) return
        call ode%locate(3, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, x, stat, msg)
        call expect('comp')
    contains
        subroutine expect(name)
            character(len=*), intent(in) :: name
            call check(error, stat, SEISPULSE_INVALID_INPUT, name//': status')
            if (allocated(error)) return
            call check(error, index(msg, name) == 1, 'message must start with '//name// &
                       ', got: '//trim(msg))
            msg = ''
        end subroutine expect
    end subroutine test_bad_input

end module test_ode
