!> Divided differences of exp, evaluated without cancellation or overflow.
!>
!> e[x0, ..., xn] = sum_k h_k(x0, ..., xn)/(k + n)! (h_k the complete symmetric polynomials)
!> is the n-th divided difference of exp; for distinct nodes it is the familiar quotient
!> recursion (e[x0, x1] = (e^x0 - e^x1)/(x0 - x1), ...), at repeated nodes its limit
!> (e[x, x] = e^x, e[x, x, x] = e^x/2). Duhamel integrals of exponential and sinusoidal
!> forcing are such differences (doc/rocking.md, doc/oscillator.md). The quotient loses
!> every digit when nodes cluster; here clustered nodes use the Taylor series about their
!> midpoint (or about 0) and spread nodes the recurrence ordered so that no large
!> cancellation occurs.
!>
!> Two families, as the solvers need them:
!> * real nodes with the exponentials supplied by the caller (seispulse_rocking_closed):
!>   `exp_dd1` e[a, b], `exp_dd2` e[x1, x2, x3], `exp_dd_pack` the set
!>   e[p, c, c + y], e[p, c, c - y], e[p, c, c + y, c - y];
!> * complex nodes (seispulse_sdof_closed): `cexp_dd1` e[x, y] and e^y, `cexp_dd2_at0`
!>   e[x, y, 0], `cexp_dd2` e[a, b, c], `cexp_dd3` e[x1, x2, x3, x4]. The elementary
!>   phi_1(z) = e[z, 0] is `phi1` of seispulse_special.
module seispulse_divided_differences
    use seispulse_kinds, only: dp
    use seispulse_special, only: phi1, phi1_taylor, complex_phis, inv_factorial
    implicit none
    private

    public :: exp_dd1, exp_dd2, exp_dd_pack
    public :: cexp_dd1, cexp_dd2_at0, cexp_dd2, cexp_dd3

    !> Real nodes: spread below which the Taylor series is used.
    real(dp), parameter :: dd_spread = 1.0_dp

contains

    ! ------------------------------------------------------------------------------
    ! Real nodes, exponentials given
    ! ------------------------------------------------------------------------------

    !> (e^a - e^b)/(a - b) from ea = e^a, eb = e^b: the quotient for |a - b| >= 1/2 (at most
    !> 1.4 bits lost), e^max phi_1(-|a - b|) closer (e^a at a = b).
    pure function exp_dd1(a, ea, b, eb) result(y)
        real(dp), intent(in) :: a    !! first node
        real(dp), intent(in) :: ea   !! e^a
        real(dp), intent(in) :: b    !! second node
        real(dp), intent(in) :: eb   !! e^b
        real(dp) :: y                !! e[a, b]
        real(dp) :: d
        d = a - b
        if (abs(d) >= 0.5_dp) then
            y = (ea - eb) / d
        else if (d >= 0.0_dp) then
            y = ea * phi1_taylor(-d)
        else
            y = eb * phi1_taylor(d)
        end if
    end function exp_dd1

    !> Second divided difference of exp at three nodes (any order, repeats allowed), given
    !> the exponentials of the nodes: the series below a spread of 1 (dd_spread), else the
    !> recurrence on sorted nodes (exp is convex: the difference of positive terms loses a few
    !> bits at most).
    pure function exp_dd2(x1, e1, x2, e2, x3, e3) result(y)
        real(dp), intent(in) :: x1, x2, x3   !! nodes
        real(dp), intent(in) :: e1, e2, e3   !! e^x1, e^x2, e^x3
        real(dp) :: y                        !! e[x1, x2, x3]
        real(dp) :: a, ea, b, eb, c, ec
        a = x1
        ea = e1
        b = x2
        eb = e2
        c = x3
        ec = e3
        call order(a, ea, b, eb)
        call order(b, eb, c, ec)
        call order(a, ea, b, eb)
        if (c - a < dd_spread) then
            y = series3(a, b, c, sqrt(ea) * sqrt(ec))
        else
            y = (exp_dd1(b, eb, c, ec) - exp_dd1(a, ea, b, eb)) / (c - a)
        end if
    end function exp_dd2

    !> The divided differences of exp the phases need, at the nodes p, c, c + y, c - y
    !> (y >= 0; ep = e^p, ec = e^c, ey = e^y): dplus = exp[p, c, c + y],
    !> dminus = exp[p, c, c - y], d3 = exp[p, c, c + y, c - y]. Clustered nodes (spread < 1):
    !> one Taylor series for all three; otherwise the recurrence on sorted nodes, whose two
    !> second differences are dplus (p >= c - y) and dminus (p <= c + y).
    pure subroutine exp_dd_pack(p, ep, c, ec, y, ey, dplus, dminus, d3)
        real(dp), intent(in) :: p        !! node p
        real(dp), intent(in) :: ep       !! e^p
        real(dp), intent(in) :: c        !! centre node c
        real(dp), intent(in) :: ec       !! e^c
        real(dp), intent(in) :: y        !! half spread y >= 0 of the nodes c - y, c + y
        real(dp), intent(in) :: ey       !! e^y
        real(dp), intent(out) :: dplus   !! e[p, c, c + y]
        real(dp), intent(out) :: dminus  !! e[p, c, c - y]
        real(dp), intent(out) :: d3      !! e[p, c, c + y, c - y]
        real(dp) :: lo, hi, elo, ehi, m, zp, zc, zu, zl, h1, h2, h3p, h3m, h4, sp, sm, s4, &
                    eu, el, upper, lower
        integer :: k
        eu = ec * ey
        el = ec / ey
        if (p < c - y) then
            lo = p
            elo = ep
        else
            lo = c - y
            elo = el
        end if
        if (p > c + y) then
            hi = p
            ehi = ep
        else
            hi = c + y
            ehi = eu
        end if
        if (hi - lo < dd_spread) then
            m = 0.5_dp * (lo + hi)
            zp = p - m
            zc = c - m
            zu = c + y - m
            zl = c - y - m
            h1 = 1.0_dp
            h2 = 1.0_dp
            h3p = 1.0_dp
            h3m = 1.0_dp
            h4 = 1.0_dp
            sp = inv_factorial(2)
            sm = inv_factorial(2)
            s4 = inv_factorial(3)
            do k = 1, series_terms(0.5_dp * (hi - lo))
                h1 = zp * h1
                h2 = h1 + zc * h2
                h3p = h2 + zu * h3p
                h3m = h2 + zl * h3m
                h4 = h3p + zl * h4
                sp = sp + h3p * inv_factorial(k + 2)
                sm = sm + h3m * inv_factorial(k + 2)
                s4 = s4 + h4 * inv_factorial(k + 3)
            end do
            m = sqrt(elo) * sqrt(ehi)
            dplus = m * sp
            dminus = m * sm
            d3 = m * s4
        else
            if (p >= c - y) then
                upper = exp_dd2(p, ep, c, ec, c + y, eu)
                dplus = upper
            else
                upper = exp_dd2(c - y, el, c, ec, c + y, eu)
                dplus = exp_dd2(p, ep, c, ec, c + y, eu)
            end if
            if (p <= c + y) then
                lower = exp_dd2(p, ep, c, ec, c - y, el)
                dminus = lower
            else
                lower = exp_dd2(c - y, el, c, ec, c + y, eu)
                dminus = exp_dd2(p, ep, c, ec, c - y, el)
            end if
            d3 = (upper - lower) / (hi - lo)
        end if
    end subroutine exp_dd_pack

    !> Number of Taylor terms for nodes within hw of their midpoint (hw <= 1): truncation
    !> below 1e-17 relative.
    pure integer function series_terms(hw) result(nt)
        real(dp), intent(in) :: hw
        if (hw > 0.5_dp) then
            nt = 20
        else if (hw > 0.125_dp) then
            nt = 16
        else if (hw > 0.01_dp) then
            nt = 11
        else
            nt = 7
        end if
    end function series_terms

    !> exp[a, b, c] for sorted nodes of spread < 1: e^m sum_k h_k(a-m, b-m, c-m)/(k + 2)!,
    !> m the midpoint (em = e^m), h_k the complete symmetric polynomials.
    pure function series3(a, b, c, em) result(y)
        real(dp), intent(in) :: a, b, c, em
        real(dp) :: y, m, za, zb, zc, ha, hab, habc, s
        integer :: k
        m = 0.5_dp * (a + c)
        za = a - m
        zb = b - m
        zc = c - m
        ha = 1.0_dp
        hab = 1.0_dp
        habc = 1.0_dp
        s = inv_factorial(2)
        do k = 1, series_terms(0.5_dp * (c - a))
            ha = za * ha
            hab = ha + zb * hab
            habc = hab + zc * habc
            s = s + habc * inv_factorial(k + 2)
        end do
        y = em * s
    end function series3

    !> Swap the pairs (a, ea), (b, eb) unless a <= b.
    pure subroutine order(a, ea, b, eb)
        real(dp), intent(inout) :: a, ea, b, eb
        real(dp) :: t
        if (a > b) then
            t = a
            a = b
            b = t
            t = ea
            ea = eb
            eb = t
        end if
    end subroutine order

    ! ------------------------------------------------------------------------------
    ! Complex nodes
    ! ------------------------------------------------------------------------------

    !> e[x, y] = (e^x - e^y)/(x - y) (e^x at x = y) and e^y. Written e^u phi_1(w - u) with u the
    !> argument of larger real part: phi_1 is taken where Re <= 0 (no overflow), exact at x = y.
    elemental subroutine cexp_dd1(x, y, e, ey)
        complex(dp), intent(in) :: x    !! first node
        complex(dp), intent(in) :: y    !! second node
        complex(dp), intent(out) :: e   !! e[x, y]
        complex(dp), intent(out) :: ey  !! e^y
        complex(dp) :: p0, p1, p2, ex
        if (real(x, dp) >= real(y, dp)) then
            call complex_phis(y - x, p0, p1, p2)
            ex = exp(x)
            e = ex * p1
            ey = ex * p0
        else
            call complex_phis(x - y, p0, p1, p2)
            ey = exp(y)
            e = ey * p1
        end if
    end subroutine cexp_dd1

    !> Second divided difference e[x, y, 0] for Re x, Re y <= 1: Taylor series
    !> sum_n h_n(x, y)/(n + 2)! (h_n the complete symmetric polynomials) when |x|, |y| <= 1;
    !> otherwise the difference quotient over the farthest pair of the three points (divisor
    !> >= 1, so the numerator's rounding is not amplified).
    pure function cexp_dd2_at0(x, y) result(e)
        complex(dp), intent(in) :: x, y   !! nodes (the third is 0), Re x, Re y <= 1
        complex(dp) :: e                  !! e[x, y, 0]
        complex(dp) :: xn, h, e1, ey
        real(dp) :: f, dxy, dx, dy
        integer :: n
        if (abs(x) <= 1.0_dp .and. abs(y) <= 1.0_dp) then
            xn = (1.0_dp, 0.0_dp)
            h = (1.0_dp, 0.0_dp)
            f = 0.5_dp
            e = 0.5_dp * h
            do n = 1, 20
                xn = xn * x
                h = y * h + xn
                f = f / real(n + 2, dp)
                e = e + f * h
            end do
        else
            dxy = abs(x - y)
            dx = abs(x)
            dy = abs(y)
            if (dxy >= dx .and. dxy >= dy) then
                e = (phi1(x) - phi1(y)) / (x - y)
            else if (dx >= dy) then
                call cexp_dd1(x, y, e1, ey)
                e = (e1 - phi1(y)) / x
            else
                call cexp_dd1(y, x, e1, ey)
                e = (e1 - phi1(x)) / y
            end if
        end if
    end function cexp_dd2_at0

    !> e[a, b, c] = e^c e[a - c, b - c, 0] with c the point of largest real part.
    pure function cexp_dd2(a, b, c) result(e)
        complex(dp), intent(in) :: a, b, c   !! nodes
        complex(dp) :: e                     !! e[a, b, c]
        if (real(a, dp) >= real(b, dp) .and. real(a, dp) >= real(c, dp)) then
            e = exp(a) * cexp_dd2_at0(b - a, c - a)
        else if (real(b, dp) >= real(c, dp)) then
            e = exp(b) * cexp_dd2_at0(a - b, c - b)
        else
            e = exp(c) * cexp_dd2_at0(a - c, b - c)
        end if
    end function cexp_dd2

    !> Third divided difference e[x1, x2, x3, x4] of exp, any points: the Taylor series when
    !> all are in the unit disk; else e^c e[x1 - c, ..., x4 - c] with c the point of largest
    !> real part (the shifted points have Re <= 0: no overflow), by the series when the
    !> shifted points are in the unit disk, else by the quotient
    !> (e[..without xb..] - e[..without xa..])/(xa - xb) over the farthest pair (one shifted
    !> point is 0, so that pair is more than 1 apart: the numerator's rounding is not
    !> amplified).
    pure function cexp_dd3(x1, x2, x3, x4) result(e)
        complex(dp), intent(in) :: x1, x2, x3, x4   !! nodes
        complex(dp) :: e                            !! e[x1, x2, x3, x4]
        complex(dp) :: x(4), y(4), q(3)
        real(dp) :: dist, dmax
        integer :: c, i, j, a, b, k
        x = [x1, x2, x3, x4]
        if (maxval(abs(x)) <= 1.0_dp) then
            e = series4c(x1, x2, x3, x4)
            return
        end if
        c = maxloc(real(x, dp), 1)
        y = x - x(c)
        if (maxval(abs(y)) <= 1.0_dp) then
            e = exp(x(c)) * series4c(y(1), y(2), y(3), y(4))
            return
        end if
        a = 1
        b = 2
        dmax = -1.0_dp
        do i = 1, 3
            do j = i + 1, 4
                dist = abs(y(i) - y(j))
                if (dist > dmax) then
                    dmax = dist
                    a = i
                    b = j
                end if
            end do
        end do
        ! e[all] = (e[all but b] - e[all but a])/(y_a - y_b)
        k = 0
        do i = 1, 4
            if (i == b) cycle
            k = k + 1
            q(k) = y(i)
        end do
        e = cexp_dd2(q(1), q(2), q(3))
        k = 0
        do i = 1, 4
            if (i == a) cycle
            k = k + 1
            q(k) = y(i)
        end do
        e = exp(x(c)) * ((e - cexp_dd2(q(1), q(2), q(3))) / (y(a) - y(b)))
    end function cexp_dd3

    !> Third divided difference e[x1, x2, x3, x4] of exp for points in the unit disk:
    !> sum_n h_n(x1..x4)/(n + 3)! (complete symmetric polynomials by the recurrence
    !> h_n(x1..xk) = h_n(x1..xk-1) + xk h_(n-1)(x1..xk); 23 terms, below 1e-20).
    pure function series4c(x1, x2, x3, x4) result(e)
        complex(dp), intent(in) :: x1, x2, x3, x4
        complex(dp) :: e, h(0:22)
        real(dp) :: f
        integer :: n
        h(0) = (1.0_dp, 0.0_dp)
        do n = 1, 22
            h(n) = x1 * h(n - 1)
        end do
        do n = 1, 22
            h(n) = h(n) + x2 * h(n - 1)
        end do
        do n = 1, 22
            h(n) = h(n) + x3 * h(n - 1)
        end do
        do n = 1, 22
            h(n) = h(n) + x4 * h(n - 1)
        end do
        f = 1.0_dp / 6.0_dp
        e = f * h(0)
        do n = 1, 22
            f = f / real(n + 3, dp)
            e = e + f * h(n)
        end do
    end function series4c

end module seispulse_divided_differences
