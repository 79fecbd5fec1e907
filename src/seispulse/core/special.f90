!> Special functions evaluated without cancellation or overflow.
!>
!> The exponential "phi functions" phi_k(x) = sum_{j>=0} x^j/(j+k)! are the
!> building blocks of every closed form for exponential pulses:
!>   phi_1(x) = (e^x - 1)/x,  phi2(x) = phi_2(x) = (e^x - 1 - x)/x^2,
!>   phi3(x) = phi_3(x) = (e^x - 1 - x - x^2/2)/x^3,   phi_k(0) = 1/k!.
!> Printed forms such as (e^x - 1 - x)/x^2 lose every digit for small |x|; here a
!> series is used for |x| < 2 and recurrences built on expm1 elsewhere (at most a
!> few ulps lost). For large positive x the scaled values e^(-x) phi_k(x) are
!> available, which never overflow (doc/pulses.md section 1).
module seispulse_special
    use, intrinsic :: iso_c_binding, only: c_double
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: expm1, log1p, exp_phis, exp_phis_scaled, phi2, phi3, sin_pi, cos_pi, exp_expm1, &
              tau_minus_sinpi, pi, complex_phis
    public :: phi1, phi1_taylor, phi1_from_exp, inv_factorial
    public :: log1p_over_x, sinh_minus_x, x_minus_asinh, x_minus_sin

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp  !! pi

    !> Series/recurrence switch for the phi functions (see exp_phis).
    real(dp), parameter :: series_limit = 2.0_dp
    !> Above this argument e^x overflows soon: switch to the scaled recurrence.
    real(dp), parameter :: scaled_limit = 700.0_dp
    !> 1/m!, m = 0..26: Taylor coefficients of exp, of the phi functions and of the divided
    !> differences of exp (seispulse_divided_differences).
    real(dp), parameter :: inv_factorial(0:26) = [ &
        1.0_dp / 1.0_dp, 1.0_dp / 1.0_dp, 1.0_dp / 2.0_dp, &
        1.0_dp / 6.0_dp, 1.0_dp / 24.0_dp, 1.0_dp / 120.0_dp, 1.0_dp / 720.0_dp, &
        1.0_dp / 5040.0_dp, 1.0_dp / 40320.0_dp, 1.0_dp / 362880.0_dp, &
        1.0_dp / 3628800.0_dp, 1.0_dp / 39916800.0_dp, 1.0_dp / 479001600.0_dp, &
        1.0_dp / 6227020800.0_dp, 1.0_dp / 87178291200.0_dp, &
        1.0_dp / 1307674368000.0_dp, 1.0_dp / 20922789888000.0_dp, &
        1.0_dp / 355687428096000.0_dp, 1.0_dp / 6402373705728000.0_dp, &
        1.0_dp / 121645100408832000.0_dp, 1.0_dp / 2432902008176640000.0_dp, &
        1.0_dp / 51090942171709440000.0_dp, 1.0_dp / 1124000727777607680000.0_dp, &
        1.0_dp / 25852016738884976640000.0_dp, 1.0_dp / 620448401733239439360000.0_dp, &
        1.0_dp / 15511210043330985984000000.0_dp, 1.0_dp / 403291461126605635584000000.0_dp]
    !> 1/(j+3)!, j = 0..23: Taylor coefficients of phi_3.
    integer, parameter :: nchi = 23
    real(dp), parameter :: chi_coef(0:nchi) = inv_factorial(3:nchi + 3)

    !> phi_1(z) = (e^z - 1)/z, real or complex, 1 at z = 0: real `phi1_real` (expm1(x)/x),
    !> complex `phi1_complex` (complex_phis).
    interface phi1
        module procedure phi1_real
        module procedure phi1_complex
    end interface phi1

    interface
        pure function c_expm1(x) bind(c, name='expm1') result(y)
            import :: c_double
            real(c_double), value, intent(in) :: x
            real(c_double) :: y
        end function c_expm1
        pure function c_log1p(x) bind(c, name='log1p') result(y)
            import :: c_double
            real(c_double), value, intent(in) :: x
            real(c_double) :: y
        end function c_log1p
    end interface

contains

    !> e^x - 1 without cancellation for small |x| (C99 libm).
    elemental function expm1(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        y = c_expm1(x)
    end function expm1

    !> log(1 + x) without cancellation for small |x| (C99 libm).
    elemental function log1p(x) result(y)
        real(dp), intent(in) :: x  !! argument, x > -1
        real(dp) :: y
        y = c_log1p(x)
    end function log1p

    !> phi_1(x), phi_2(x), phi_3(x) together, for x <= 700.
    !> Relative error a few ulps; exact limits 1, 1/2, 1/6 at x = 0.
    elemental subroutine exp_phis(x, p1, p2, p3)
        real(dp), intent(in) :: x    !! argument (x <= 700; larger overflows: use the scaled form)
        real(dp), intent(out) :: p1  !! (e^x - 1)/x
        real(dp), intent(out) :: p2  !! (e^x - 1 - x)/x^2
        real(dp), intent(out) :: p3  !! (e^x - 1 - x - x^2/2)/x^3
        real(dp) :: r
        if (abs(x) < series_limit) then
            ! backward recurrence phi_k = 1/k! + x phi_(k+1): at worst (x = -2) the sum
            ! cancels to 1/3.6 of its terms, about 2 bits, and saves a call to exp
            p3 = chi_series(x)
            p2 = 0.5_dp + x * p3
            p1 = 1.0_dp + x * p2
        else
            ! Forward recurrence phi_(k+1) = (phi_k - 1/k!)/x; for |x| >= 2 each step
            ! loses at most about 1.5 bits. exp(x) - 1 is as good as expm1 here and
            ! several times faster; one reciprocal instead of three divisions costs
            ! half an ulp per step.
            r = 1.0_dp / x
            p1 = (exp(x) - 1.0_dp) * r
            p2 = (p1 - 1.0_dp) * r
            p3 = (p2 - 0.5_dp) * r
        end if
    end subroutine exp_phis

    !> Scaled values q_k = e^(-x) phi_k(x), k = 1, 2, 3, for x >= 0: finite for any x
    !> (q_k ~ 1/x^k as x -> +inf).
    elemental subroutine exp_phis_scaled(x, q1, q2, q3)
        real(dp), intent(in) :: x    !! argument, x >= 0 (may be huge)
        real(dp), intent(out) :: q1  !! e^(-x) phi_1(x) = (1 - e^(-x))/x
        real(dp), intent(out) :: q2  !! e^(-x) phi_2(x)
        real(dp), intent(out) :: q3  !! e^(-x) phi_3(x)
        real(dp) :: p1, p2, p3, emx
        if (x <= scaled_limit) then
            call exp_phis(x, p1, p2, p3)
            emx = exp(-x)
            q1 = emx * p1
            q2 = emx * p2
            q3 = emx * p3
        else
            ! e^(-x) is below 1e-304 here, so the recurrence subtracts nothing visible.
            emx = exp(-x)
            q1 = -expm1(-x) / x
            q2 = (q1 - emx) / x
            q3 = (q2 - 0.5_dp * emx) / x
        end if
    end subroutine exp_phis_scaled

    !> phi_1(x) = (e^x - 1)/x = expm1(x)/x, 1 at x = 0, any real x (one division: relative
    !> error about 1 ulp; +inf past x = 709.78 where e^x overflows). exp_phis gives the same
    !> function from its series/recurrence, to a few ulps, together with phi_2 and phi_3.
    elemental function phi1_real(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        if (abs(x) > 0.0_dp) then
            y = expm1(x) / x
        else
            y = 1.0_dp
        end if
    end function phi1_real

    !> phi_1(z) = (e^z - 1)/z of a complex z, 1 at z = 0 (the p1 of complex_phis: series for
    !> |Re z| + |Im z| <= 1, else the quotient on e^z; Re z below 709).
    elemental function phi1_complex(z) result(p1)
        complex(dp), intent(in) :: z  !! argument
        complex(dp) :: p1
        complex(dp) :: p0, p2
        call complex_phis(z, p0, p1, p2)
    end function phi1_complex

    !> phi_1(z) for |z| <= 1/2: Taylor polynomial sum_{k=0}^{14} z^k/(k+1)! by Horner
    !> (truncation below 2^-53 relative there; usable but less accurate up to |z| ~ 1).
    elemental function phi1_taylor(z) result(y)
        real(dp), intent(in) :: z  !! argument, |z| <= 1/2
        real(dp) :: y
        integer :: k
        y = inv_factorial(15)
        do k = 13, 0, -1
            y = inv_factorial(k + 1) + z * y
        end do
    end function phi1_taylor

    !> phi_1(x) = (e^x - 1)/x from ex = e^x computed by the caller: the quotient for
    !> |x| >= 1/2 (e^x - 1 loses at most about one bit there), phi1_taylor closer to 0.
    elemental function phi1_from_exp(x, ex) result(y)
        real(dp), intent(in) :: x   !! argument
        real(dp), intent(in) :: ex  !! e^x
        real(dp) :: y
        if (abs(x) >= 0.5_dp) then
            y = (ex - 1.0_dp) / x
        else
            y = phi1_taylor(x)
        end if
    end function phi1_from_exp

    !> ln(1 + x)/x, 1 at x = 0 (x > -1).
    elemental function log1p_over_x(x) result(y)
        real(dp), intent(in) :: x  !! argument, x > -1
        real(dp) :: y
        if (abs(x) > 0.0_dp) then
            y = log1p(x) / x
        else
            y = 1.0_dp
        end if
    end function log1p_over_x

    !> sinh(x) - x (Taylor series for |x| < 1, to x^19/19!).
    elemental function sinh_minus_x(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        real(dp) :: x2
        integer :: k
        if (abs(x) < 1.0_dp) then
            x2 = x * x
            y = 1.0_dp
            do k = 9, 2, -1
                y = 1.0_dp + y * x2 / real((2 * k) * (2 * k + 1), dp)
            end do
            y = x * x2 / 6.0_dp * y
        else
            y = sinh(x) - x
        end if
    end function sinh_minus_x

    !> x - asinh(x) (series sum_n (-1)^(n+1) t_n x^(2n+1)/(2n+1), t_n = (2n)!/(4^n n!^2),
    !> for |x| < 1/4).
    elemental function x_minus_asinh(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        real(dp) :: x2, t, term
        integer :: n
        if (abs(x) < 0.25_dp) then
            x2 = x * x
            t = 1.0_dp
            term = x
            y = 0.0_dp
            do n = 1, 14
                t = t * real(2 * n - 1, dp) / real(2 * n, dp)
                term = -term * x2
                y = y - t * term / real(2 * n + 1, dp)
            end do
        else
            y = x - asinh(x)
        end if
    end function x_minus_asinh

    !> x - sin(x) without cancellation near x = 0 (Taylor series for |x| < 1, to x^21/21!;
    !> the remaining terms are below 1e-17 relative). Odd in x; used by the contact integrals
    !> of the Winkler footings (doc/winkler.md section 2).
    elemental function x_minus_sin(x) result(y)
        real(dp), intent(in) :: x  !! argument (rad)
        real(dp) :: y
        real(dp) :: x2
        integer :: k
        if (abs(x) < 1.0_dp) then
            ! x^3/3! (1 - x^2/(4 5) (1 - x^2/(6 7) (1 - ...)))
            x2 = x * x
            y = 1.0_dp
            do k = 10, 2, -1
                y = 1.0_dp - y * x2 / real((2 * k) * (2 * k + 1), dp)
            end do
            y = x * x2 / 6.0_dp * y
        else
            y = x - sin(x)
        end if
    end function x_minus_sin

    !> phi2(x) = (e^x - 1 - x)/x^2, phi2(0) = 1/2 (x <= 700).
    elemental function phi2(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        real(dp) :: p1, p3
        call exp_phis(x, p1, y, p3)
    end function phi2

    !> phi3(x) = (e^x - 1 - x - x^2/2)/x^3, phi3(0) = 1/6 (x <= 700).
    elemental function phi3(x) result(y)
        real(dp), intent(in) :: x  !! argument
        real(dp) :: y
        real(dp) :: p1, p2
        call exp_phis(x, p1, p2, y)
    end function phi3

    !> Taylor series of phi_3: the even and odd coefficients by two independent
    !> Horner chains in x^2 (half the latency of one chain); the number of terms
    !> grows with |x| (truncation below 1e-17 relative for |x| < 2).
    pure function chi_series(x) result(y)
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: x2, even, odd
        integer :: j, n
        if (abs(x) < 0.125_dp) then
            n = 9
        else if (abs(x) < 0.5_dp) then
            n = 13
        else
            n = nchi
        end if
        if (mod(n, 2) == 0) n = n + 1      ! n odd: chi_coef(n) closes the odd chain
        x2 = x * x
        even = chi_coef(n - 1)
        odd = chi_coef(n)
        do j = n - 3, 0, -2
            even = chi_coef(j) + x2 * even
            odd = chi_coef(j + 1) + x2 * odd
        end do
        y = even + x * odd
    end function chi_series

    !> sin(pi x) with exact argument reduction (zero at every integer).
    elemental function sin_pi(x) result(y)
        real(dp), intent(in) :: x  !! argument (finite)
        real(dp) :: y
        real(dp) :: r
        r = x - 2.0_dp * anint(0.5_dp * x)    ! exact: r in [-1, 1], same sin(pi r)
        if (r > 0.5_dp) then
            r = 1.0_dp - r                     ! sin(pi r) = sin(pi (1 - r))
        else if (r < -0.5_dp) then
            r = -1.0_dp - r
        end if
        y = sin(pi * r)
    end function sin_pi

    !> cos(pi x) with exact argument reduction (zero at every half-integer).
    elemental function cos_pi(x) result(y)
        real(dp), intent(in) :: x  !! argument (finite)
        real(dp) :: y
        y = sin_pi(0.5_dp - abs(x - 2.0_dp * anint(0.5_dp * x)))
    end function cos_pi

    !> t - sin(pi t)/pi without cancellation near t = 0 (series for |t| < 1/2).
    elemental function tau_minus_sinpi(t) result(y)
        real(dp), intent(in) :: t  !! argument (finite)
        real(dp) :: y
        real(dp) :: x, x2, term
        integer :: j
        if (abs(t) < 0.5_dp) then
            ! (x - sin x)/pi = sum_{j>=1} (-1)^(j+1) x^(2j+1)/(2j+1)!/pi, x = pi t
            x = pi * t
            x2 = x * x
            term = x * x2 / 6.0_dp
            y = term
            do j = 2, 12
                term = -term * x2 / real((2 * j) * (2 * j + 1), dp)
                y = y + term
            end do
            y = y / pi
        else
            y = t - sin_pi(t) / pi
        end if
    end function tau_minus_sinpi

    !> e^z, phi_1(z) = (e^z - 1)/z and phi_2(z) = (e^z - 1 - z)/z^2 of a complex z,
    !> without cancellation near z = 0: Taylor series of phi_2 (Horner, 18 terms, error
    !> below 1e-17) for |z| <= 1, then phi_1 = 1 + z phi_2 and e^z = 1 + z phi_1;
    !> the recurrences on e^z elsewhere (few ulps lost, absolute where phi_k has a
    !> complex zero). The caller keeps Re z below 709 (no overflow guard here: the
    !> oscillator solvers only pass Re z <= 0 or a bounded shift).
    elemental subroutine complex_phis(z, p0, p1, p2)
        complex(dp), intent(in) :: z    !! argument
        complex(dp), intent(out) :: p0  !! e^z
        complex(dp), intent(out) :: p1  !! phi_1(z)
        complex(dp), intent(out) :: p2  !! phi_2(z)
        integer :: j
        if (abs(real(z, dp)) + abs(aimag(z)) <= 1.0_dp) then
            ! 1/(j+2)! = chi_coef(j-1), j >= 1
            p2 = cmplx(chi_coef(17), 0.0_dp, dp)
            do j = 17, 1, -1
                p2 = chi_coef(j - 1) + z * p2
            end do
            p2 = 0.5_dp + z * p2
            p1 = 1.0_dp + z * p2
            p0 = 1.0_dp + z * p1
        else
            p0 = exp(z)
            p1 = (p0 - 1.0_dp) / z
            p2 = (p1 - 1.0_dp) / z
        end if
    end subroutine complex_phis

    !> e^z and e^z - 1 of a complex z with Re z <= 0, the second without cancellation:
    !> expm1(x + i y) = expm1(x) cos y - 2 sin^2(y/2) + i e^x sin y (complex_phis' e^z - 1
    !> loses relative accuracy near z = 2 pi i k). Used by the wall solutions for the
    !> decay exp(-a x) and 1 - exp(-a x) of a mode.
    elemental subroutine exp_expm1(z, e, em1)
        complex(dp), intent(in) :: z    !! argument, Re z <= 0 (no overflow guard)
        complex(dp), intent(out) :: e   !! e^z
        complex(dp), intent(out) :: em1 !! e^z - 1
        real(dp) :: ex, c, s, h
        ex = exp(real(z, dp))
        c = cos(aimag(z))
        s = sin(aimag(z))
        h = sin(0.5_dp*aimag(z))
        e = ex*cmplx(c, s, dp)
        em1 = cmplx(expm1(real(z, dp))*c - 2.0_dp*h*h, ex*s, dp)
    end subroutine exp_expm1

end module seispulse_special
