!> Bracketed root finding that always terminates with a status (Brent 1973).
!>
!> A problem supplies its function by extending `scalar_function` and
!> implementing `eval`; the extension carries the parameters, so no global state
!> and no internal-procedure trampolines (which need an executable stack) are used.
module seispulse_roots
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_NO_BRACKET, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    implicit none
    private

    public :: scalar_function, find_root, smooth_function, find_root_newton, find_minimum

    !> A real function of one real variable, with its parameters as components.
    type, abstract :: scalar_function
    contains
        procedure(scalar_eval), deferred :: eval
    end type scalar_function

    abstract interface
        !> Value of the function at x.
        function scalar_eval(self, x) result(y)
            import :: scalar_function, dp
            class(scalar_function), intent(inout) :: self  !! the function and its parameters
            real(dp), intent(in) :: x                      !! abscissa
            real(dp) :: y
        end function scalar_eval
    end interface

    !> A function with its derivative, for `find_root_newton`.
    type, abstract, extends(scalar_function) :: smooth_function
    contains
        procedure(value_and_slope), deferred :: eval_slope
    end type smooth_function

    abstract interface
        !> Value y = f(x) and derivative dy = f'(x).
        subroutine value_and_slope(self, x, y, dy)
            import :: smooth_function, dp
            class(smooth_function), intent(inout) :: self  !! the function and its parameters
            real(dp), intent(in) :: x                      !! abscissa
            real(dp), intent(out) :: y                     !! f(x)
            real(dp), intent(out) :: dy                    !! f'(x)
        end subroutine value_and_slope
    end interface

contains

    !> Find x in [a, b] with f(x) = 0, given f(a) f(b) <= 0, by Newton steps kept inside
    !> the bracket (rtsafe): a step that would leave the bracket, or that does not halve
    !> the previous one, is replaced by bisection, and the bracket shrinks at every
    !> evaluation. Quadratic convergence where Newton works, bisection's guarantee
    !> otherwise; the same convergence test, statuses and evaluation limit as `find_root`.
    !> For problems whose derivative is cheap next to the value.
    recursive subroutine find_root_newton(f, a, b, x, stat, errmsg, max_iter, fa_known, &
                                          fb_known, n_eval)
        class(smooth_function), intent(inout) :: f            !! function whose root is sought
        real(dp), intent(in) :: a                             !! one end of the bracket
        real(dp), intent(in) :: b                             !! other end of the bracket
        real(dp), intent(out) :: x                            !! the root (best estimate)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: max_iter             !! evaluation limit (default 1000)
        !> f(a), if the caller has it; absent: evaluated
        real(dp), intent(in), optional :: fa_known
        !> f(b), if the caller has it; absent: evaluated
        real(dp), intent(in), optional :: fb_known
        integer, intent(out), optional :: n_eval              !! evaluations used
        real(dp) :: fa, fb, xl, xh, fx, dfx, step, step_old, tol
        integer :: iter, limit, evals
        logical :: done
        limit = 1000
        if (present(max_iter)) limit = max_iter
        call open_bracket(f, a, b, fa_known, fb_known, fa, fb, x, evals, stat, errmsg, done)
        if (done) then
            call report_evals()
            return
        end if
        ! xl: the end where f < 0, xh: where f > 0
        if (fa < 0.0_dp) then
            xl = a
            xh = b
        else
            xl = b
            xh = a
        end if
        ! start from the secant point of the bracket
        x = a - fa * ((b - a) / (fb - fa))
        step_old = abs(b - a)
        step = step_old
        call f%eval_slope(x, fx, dfx)
        evals = evals + 1
        do iter = 1, limit
            if (.not. (ieee_is_finite(fx) .and. ieee_is_finite(dfx))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                               'function: value inside the bracket is not a finite number')
                call report_evals()
                return
            end if
            if (is_zero(fx)) then
                call report_evals()
                return
            end if
            if (fx < 0.0_dp) then
                xl = x
            else
                xh = x
            end if
            tol = 2.0_dp * epsilon(1.0_dp) * abs(x)
            if (.not. (abs(xh - xl) > 2.0_dp * tol)) then
                call report_evals()
                return
            end if
            if (((x - xh) * dfx - fx) * ((x - xl) * dfx - fx) > 0.0_dp &
                .or. abs(2.0_dp * fx) > abs(step_old * dfx)) then
                ! Newton would leave the bracket or converges too slowly: bisect
                step_old = step
                step = 0.5_dp * (xh - xl)
                x = xl + step
            else
                step_old = step
                step = fx / dfx
                x = x - step
            end if
            if (.not. (abs(step) > tol)) then
                call report_evals()
                return
            end if
            call f%eval_slope(x, fx, dfx)
            evals = evals + 1
            if (evals >= limit) exit
        end do
        call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, &
                       'root: iteration limit reached before the bracket closed')
        call report_evals()

    contains

        subroutine report_evals()
            if (present(n_eval)) n_eval = evals
        end subroutine report_evals

    end subroutine find_root_newton

    !> Find x in [a, b] with f(x) = 0, given f(a) f(b) <= 0 (Brent's method:
    !> inverse quadratic interpolation, secant and bisection steps; the bracket
    !> always contains a sign change, so the method cannot leave it).
    !>
    !> Converged when the bracket is narrower than 4 eps |x| + xtol. Termination
    !> is guaranteed: after `max_iter` evaluations stat = SEISPULSE_NO_CONVERGENCE
    !> and x is the best point found. Recursive: f may itself solve with find_root
    !> (nested solves, e.g. a root in a parameter of a root).
    recursive subroutine find_root(f, a, b, x, stat, errmsg, xtol, max_iter, fa_known, &
                                   fb_known, n_eval)
        class(scalar_function), intent(inout) :: f            !! function whose root is sought
        real(dp), intent(in) :: a                             !! one end of the bracket
        real(dp), intent(in) :: b                             !! other end of the bracket
        real(dp), intent(out) :: x                            !! the root (best estimate)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: xtol                !! absolute tolerance in x (default 0)
        integer, intent(in), optional :: max_iter             !! evaluation limit (default 1000)
        !> f(a), if the caller has it; absent: evaluated
        real(dp), intent(in), optional :: fa_known
        !> f(b), if the caller has it; absent: evaluated
        real(dp), intent(in), optional :: fb_known
        integer, intent(out), optional :: n_eval              !! evaluations used
        real(dp) :: xa, xb, xc, fa, fb, fc, d, e, tol1, xm, p, q, r, s, abs_tol
        integer :: iter, limit, evals
        logical :: done

        abs_tol = 0.0_dp
        if (present(xtol)) abs_tol = max(xtol, 0.0_dp)
        limit = 1000
        if (present(max_iter)) limit = max_iter
        call open_bracket(f, a, b, fa_known, fb_known, fa, fb, x, evals, stat, errmsg, done)
        if (done) then
            call report_evals()
            return
        end if
        xa = a
        xb = b

        xc = xb
        fc = fb
        d = xb - xa
        e = d
        do iter = 1, limit
            if ((fb > 0.0_dp .and. fc > 0.0_dp) .or. (fb < 0.0_dp .and. fc < 0.0_dp)) then
                ! keep the sign change between b and c
                xc = xa
                fc = fa
                d = xb - xa
                e = d
            end if
            if (abs(fc) < abs(fb)) then
                ! b is the best estimate so far
                xa = xb
                xb = xc
                xc = xa
                fa = fb
                fb = fc
                fc = fa
            end if
            tol1 = 2.0_dp * epsilon(1.0_dp) * abs(xb) + 0.5_dp * abs_tol
            xm = 0.5_dp * (xc - xb)
            if (abs(xm) <= tol1 .or. is_zero(fb)) then
                x = xb
                call report_evals()
                return
            end if
            if (abs(e) >= tol1 .and. abs(fa) > abs(fb)) then
                s = fb / fa
                if (is_zero(xa - xc)) then
                    ! secant step
                    p = 2.0_dp * xm * s
                    q = 1.0_dp - s
                else
                    ! inverse quadratic interpolation
                    q = fa / fc
                    r = fb / fc
                    p = s * (2.0_dp * xm * q * (q - r) - (xb - xa) * (r - 1.0_dp))
                    q = (q - 1.0_dp) * (r - 1.0_dp) * (s - 1.0_dp)
                end if
                if (p > 0.0_dp) q = -q
                p = abs(p)
                if (2.0_dp * p < min(3.0_dp * xm * q - abs(tol1 * q), abs(e * q))) then
                    e = d            ! interpolation accepted
                    d = p / q
                else
                    d = xm           ! fall back to bisection
                    e = d
                end if
            else
                d = xm
                e = d
            end if
            xa = xb
            fa = fb
            if (abs(d) > tol1) then
                xb = xb + d
            else
                xb = xb + sign(tol1, xm)
            end if
            fb = f%eval(xb)
            evals = evals + 1
            if (.not. ieee_is_finite(fb)) then
                x = xa
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                               'function: value inside the bracket is not a finite number')
                call report_evals()
                return
            end if
        end do
        x = xb
        call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, &
                       'root: iteration limit reached before the bracket closed')
        call report_evals()

    contains

        subroutine report_evals()
            if (present(n_eval)) n_eval = evals
        end subroutine report_evals

    end subroutine find_root

    !> Minimum of f on [a, b] (Brent 1973, "fmin": golden-section steps with parabolic
    !> interpolation; the search never leaves [a, b] and never evaluates the ends). Converged
    !> when x is within 2 (sqrt(eps) |x| + xtol/3) of the minimiser; the minimum value fx is
    !> then correct to about eps relative where f is smooth. For a maximum, let f return -g.
    !> Termination is guaranteed: after `max_iter` evaluations stat = SEISPULSE_NO_CONVERGENCE
    !> with the best point found. A minimum at an end is approached, not reached: a caller
    !> that may have one compares with f(a) and f(b).
    recursive subroutine find_minimum(f, a, b, x, fx, stat, errmsg, xtol, max_iter)
        class(scalar_function), intent(inout) :: f            !! function to minimise
        real(dp), intent(in) :: a                             !! one end of the interval
        real(dp), intent(in) :: b                             !! other end of the interval
        real(dp), intent(out) :: x                            !! the minimiser (best estimate)
        real(dp), intent(out) :: fx                           !! f(x)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), intent(in), optional :: xtol                !! absolute tolerance in x (default 0)
        integer, intent(in), optional :: max_iter             !! evaluation limit (default 500)
        real(dp), parameter :: cgold = 0.38196601125010515_dp  ! (3 - sqrt(5))/2
        real(dp) :: lo, hi, v, w, fv, fw, d, e, xm, tol1, tol2, p, q, r, u, fu, abs_tol, rel
        integer :: iter, limit

        abs_tol = 0.0_dp
        if (present(xtol)) abs_tol = max(xtol, 0.0_dp)
        limit = 500
        if (present(max_iter)) limit = max_iter
        x = a
        fx = 0.0_dp
        if (.not. (ieee_is_finite(a) .and. ieee_is_finite(b))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'interval: both ends must be finite numbers')
            return
        end if
        stat = SEISPULSE_SUCCESS
        rel = sqrt(epsilon(1.0_dp))
        lo = min(a, b)
        hi = max(a, b)
        x = lo + cgold * (hi - lo)
        w = x
        v = x
        d = 0.0_dp
        e = 0.0_dp
        fx = f%eval(x)
        fv = fx
        fw = fx
        do iter = 1, limit
            if (.not. ieee_is_finite(fx)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                               'function: value inside the interval is not a finite number')
                return
            end if
            xm = 0.5_dp * (lo + hi)
            tol1 = rel * abs(x) + abs_tol / 3.0_dp + tiny(1.0_dp)
            tol2 = 2.0_dp * tol1
            if (abs(x - xm) <= tol2 - 0.5_dp * (hi - lo)) return
            if (abs(e) > tol1) then
                ! parabola through (v, fv), (w, fw), (x, fx)
                r = (x - w) * (fx - fv)
                q = (x - v) * (fx - fw)
                p = (x - v) * q - (x - w) * r
                q = 2.0_dp * (q - r)
                if (q > 0.0_dp) p = -p
                q = abs(q)
                r = e
                e = d
                if (abs(p) >= abs(0.5_dp * q * r) .or. p <= q * (lo - x) &
                    .or. p >= q * (hi - x)) then
                    if (x >= xm) then
                        e = lo - x
                    else
                        e = hi - x
                    end if
                    d = cgold * e
                else
                    d = p / q
                    u = x + d
                    if (u - lo < tol2 .or. hi - u < tol2) d = sign(tol1, xm - x)
                end if
            else
                if (x >= xm) then
                    e = lo - x
                else
                    e = hi - x
                end if
                d = cgold * e
            end if
            if (abs(d) >= tol1) then
                u = x + d
            else
                u = x + sign(tol1, d)
            end if
            fu = f%eval(u)
            if (.not. ieee_is_finite(fu)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                               'function: value inside the interval is not a finite number')
                return
            end if
            if (fu <= fx) then
                if (u >= x) then
                    lo = x
                else
                    hi = x
                end if
                v = w
                fv = fw
                w = x
                fw = fx
                x = u
                fx = fu
            else
                if (u < x) then
                    lo = u
                else
                    hi = u
                end if
                if (fu <= fw .or. is_zero(w - x)) then
                    v = w
                    fv = fw
                    w = u
                    fw = fu
                else if (fu <= fv .or. is_zero(v - x) .or. is_zero(v - w)) then
                    v = u
                    fv = fu
                end if
            end if
        end do
        call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, &
                       'minimum: iteration limit reached before the interval closed')
    end subroutine find_minimum

    !> The start both root finders share: f at the ends (unless the caller knows it), the
    !> checks, a zero at an end, the sign change. done: x is final or stat /= 0.
    recursive subroutine open_bracket(f, a, b, fa_known, fb_known, fa, fb, x, evals, stat, &
                                      errmsg, done)
        class(scalar_function), intent(inout) :: f
        real(dp), intent(in) :: a, b
        real(dp), intent(in), optional :: fa_known, fb_known
        real(dp), intent(out) :: fa, fb, x
        integer, intent(out) :: evals, stat
        character(len=*), intent(inout), optional :: errmsg
        logical, intent(out) :: done
        evals = 0
        x = a
        fa = 0.0_dp
        fb = 0.0_dp
        done = .true.
        if (.not. (ieee_is_finite(a) .and. ieee_is_finite(b))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'bracket: both ends must be finite numbers')
            return
        end if
        if (present(fa_known)) then
            fa = fa_known
        else
            fa = f%eval(a)
            evals = evals + 1
        end if
        if (present(fb_known)) then
            fb = fb_known
        else
            fb = f%eval(b)
            evals = evals + 1
        end if
        if (.not. (ieee_is_finite(fa) .and. ieee_is_finite(fb))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'bracket: function value at an end is not a finite number')
            return
        end if
        stat = SEISPULSE_SUCCESS
        if (is_zero(fa)) return
        x = b
        if (is_zero(fb)) return
        if ((fa > 0.0_dp .and. fb > 0.0_dp) .or. (fa < 0.0_dp .and. fb < 0.0_dp)) then
            x = a
            call set_error(stat, errmsg, SEISPULSE_NO_BRACKET, &
                           'bracket: f(a) and f(b) have the same sign')
            return
        end if
        done = .false.
    end subroutine open_bracket

    !> True for +0 and -0 (avoids an equality test on reals).
    elemental logical function is_zero(v)
        real(dp), intent(in) :: v
        is_zero = .not. (abs(v) > 0.0_dp)
    end function is_zero

end module seispulse_roots
