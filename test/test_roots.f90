!> Brent root finder: known roots, tolerance, statuses, bounded work.
module test_roots
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_NO_BRACKET, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE
    use seispulse_roots, only: scalar_function, find_root, smooth_function, find_root_newton
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_roots

    !> f(x) = x^3 - 2x - 5 (Wallis' equation), or cos x - x, or a step with a NaN.
    type, extends(scalar_function) :: sample_function
        integer :: which = 1
        integer :: calls = 0
    contains
        procedure :: eval => sample_eval
    end type sample_function

    !> With derivatives: Wallis' cubic, atan(x - 1/3) (plain Newton diverges from
    !> |x - 1/3| > 1.39), or a NaN beyond x = 0.3.
    type, extends(smooth_function) :: smooth_sample
        integer :: which = 1
    contains
        procedure :: eval => smooth_sample_eval
        procedure :: eval_slope => smooth_sample_slope
    end type smooth_sample

contains

    subroutine collect_roots(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('Wallis cubic to full precision', test_wallis), &
                 new_unittest('cos x = x', test_dottie), &
                 new_unittest('root at a bracket end', test_endpoint), &
                 new_unittest('no sign change is a status', test_no_bracket), &
                 new_unittest('NaN inside the bracket is a status', test_nan), &
                 new_unittest('iteration limit is a status', test_limit), &
                 new_unittest('discontinuous sign change terminates', test_step), &
                 new_unittest('safeguarded Newton: Wallis cubic, few evaluations', &
                              test_newton_wallis), &
                 new_unittest('safeguarded Newton: stays in the bracket where Newton diverges', &
                              test_newton_atan), &
                 new_unittest('safeguarded Newton: statuses', test_newton_status)]
    end subroutine collect_roots

    function sample_eval(self, x) result(y)
        class(sample_function), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        self%calls = self%calls + 1
        select case (self%which)
        case (1)
            y = (x * x - 2.0_dp) * x - 5.0_dp
        case (2)
            y = cos(x) - x
        case (3)
            if (x > 0.3_dp) then
                y = ieee_value(y, ieee_quiet_nan)
            else
                y = x - 0.5_dp
            end if
        case default
            ! sign change without a zero: the root finder must close on x = 1/3
            if (x < 1.0_dp / 3.0_dp) then
                y = -1.0_dp
            else
                y = 1.0_dp
            end if
        end select
    end function sample_eval

    subroutine test_wallis(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat, n
        f%which = 1
        call find_root(f, 2.0_dp, 3.0_dp, x, stat, n_eval=n)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        ! 2.0945514815423265914823865405793029638573 (published value)
        call check(error, x, 2.0945514815423265915_dp, rtol=4.0e-16_dp)
        if (allocated(error)) return
        call check(error, n < 15, 'Brent needs few evaluations here')
    end subroutine test_wallis

    subroutine test_dottie(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat
        f%which = 2
        call find_root(f, 1.0_dp, 0.0_dp, x, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, x, 0.73908513321516064166_dp, rtol=4.0e-16_dp)
    end subroutine test_dottie

    subroutine test_endpoint(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat
        f%which = 1
        call find_root(f, 2.0_dp, 3.0_dp, x, stat, fa_known=0.0_dp)
        call check(error, stat == SEISPULSE_SUCCESS .and. x >= 2.0_dp .and. x <= 2.0_dp, &
                   'a known zero at a is returned as is')
    end subroutine test_endpoint

    subroutine test_no_bracket(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat
        character(len=120) :: msg
        f%which = 1
        msg = ''
        call find_root(f, 3.0_dp, 4.0_dp, x, stat, msg)
        call check(error, stat, SEISPULSE_NO_BRACKET, 'status')
        if (allocated(error)) return
        call check(error, index(msg, 'same sign') > 0, 'message: '//trim(msg))
    end subroutine test_no_bracket

    subroutine test_nan(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat
        f%which = 3
        call find_root(f, 0.0_dp, 0.25_dp, x, stat)
        call check(error, stat, SEISPULSE_NO_BRACKET, 'no sign change on [0, 0.25]')
        if (allocated(error)) return
        call find_root(f, 0.0_dp, 1.0_dp, x, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'NaN at the end b')
    end subroutine test_nan

    subroutine test_limit(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat
        f%which = 1
        call find_root(f, 2.0_dp, 3.0_dp, x, stat, max_iter=2)
        call check(error, stat, SEISPULSE_NO_CONVERGENCE, 'status')
        if (allocated(error)) return
        call check(error, x > 2.0_dp .and. x < 3.0_dp, 'best point stays in the bracket')
    end subroutine test_limit

    subroutine test_step(error)
        type(test_error), allocatable, intent(out) :: error
        type(sample_function) :: f
        real(dp) :: x
        integer :: stat, n
        f%which = 4
        call find_root(f, 0.0_dp, 1.0_dp, x, stat, n_eval=n)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, x, 1.0_dp / 3.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, n <= 70, 'bisection bound ~ 60 evaluations')
    end subroutine test_step

    function smooth_sample_eval(self, x) result(y)
        class(smooth_sample), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y, dy
        call self%eval_slope(x, y, dy)
    end function smooth_sample_eval

    subroutine smooth_sample_slope(self, x, y, dy)
        class(smooth_sample), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: y, dy
        select case (self%which)
        case (1)
            y = (x * x - 2.0_dp) * x - 5.0_dp
            dy = 3.0_dp * x * x - 2.0_dp
        case (2)
            y = atan(x - 1.0_dp / 3.0_dp)
            dy = 1.0_dp / (1.0_dp + (x - 1.0_dp / 3.0_dp)**2)
        case default
            if (x > 0.3_dp) then
                y = ieee_value(y, ieee_quiet_nan)
            else
                y = x - 0.5_dp
            end if
            dy = 1.0_dp
        end select
    end subroutine smooth_sample_slope

    subroutine test_newton_wallis(error)
        type(test_error), allocatable, intent(out) :: error
        type(smooth_sample) :: f
        real(dp) :: x
        integer :: stat, n
        f%which = 1
        call find_root_newton(f, 2.0_dp, 3.0_dp, x, stat, n_eval=n)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, x, 2.0945514815423265915_dp, rtol=4.0e-16_dp)
        if (allocated(error)) return
        call check(error, n <= 8, 'quadratic convergence: few evaluations')
    end subroutine test_newton_wallis

    subroutine test_newton_atan(error)
        type(test_error), allocatable, intent(out) :: error
        type(smooth_sample) :: f
        real(dp) :: x
        integer :: stat, n
        f%which = 2
        call find_root_newton(f, -20.0_dp, 3.0_dp, x, stat, n_eval=n)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, x, 1.0_dp / 3.0_dp, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, n <= 40, 'bisection steps, then Newton')
    end subroutine test_newton_atan

    subroutine test_newton_status(error)
        type(test_error), allocatable, intent(out) :: error
        type(smooth_sample) :: f
        real(dp) :: x
        integer :: stat
        f%which = 1
        call find_root_newton(f, 3.0_dp, 4.0_dp, x, stat)
        call check(error, stat, SEISPULSE_NO_BRACKET, 'no sign change')
        if (allocated(error)) return
        call find_root_newton(f, 2.0_dp, 3.0_dp, x, stat, max_iter=2)
        call check(error, stat, SEISPULSE_NO_CONVERGENCE, 'iteration limit')
        if (allocated(error)) return
        call check(error, x > 2.0_dp .and. x < 3.0_dp, 'best point stays in the bracket')
        if (allocated(error)) return
        f%which = 3
        call find_root_newton(f, 0.0_dp, 1.0_dp, x, stat, fb_known=1.0_dp)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'NaN inside the bracket')
    end subroutine test_newton_status

end module test_roots
