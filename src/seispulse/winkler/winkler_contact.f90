!> Contact integrals of a rigid footing on tensionless Winkler springs (doc/winkler.md
!> section 2): the moments m_j = integral_{s_a}^{s_b} s^j 2 w(s) ds, j = 0, 1, 2, of a strip
!> of the base between two lines normal to the rocking diameter, s the coordinate along that
!> diameter from the base centre (m) and 2 w(s) the full width of the base at s (m):
!> w = sqrt(r^2 - s^2) for a circle of radius r, w = alpha for a rectangle of half-length
!> alpha. The strip ends are given by their distances to the two edges s = -r and s = +r, so a
!> contact strip of width b at an edge is passed exactly (d = 0 and d = b) and no digit is
!> lost for a sliver at an edge or in the interior (W.2)-(W.6).
!> Units: m; m0 in m^2, m1 in m^3, m2 in m^4.
module seispulse_winkler_contact
    use seispulse_kinds, only: dp
    use seispulse_special, only: x_minus_sin
    implicit none
    private

    public :: FOOTING_CIRCLE, FOOTING_RECTANGLE
    public :: strip_moments

    integer, parameter :: FOOTING_CIRCLE = 1     !! circular base, radius r
    integer, parameter :: FOOTING_RECTANGLE = 2  !! rectangular base, half-width r (rocking
                                                 !! direction) x half-length alpha

contains

    !> Moments m(0:2) = [m0 (m^2), m1 (m^3), m2 (m^4)] of the strip s in [s_a, s_b] of a
    !> circle of radius r or of a rectangle of half-width r and half-length alpha (W.2)-(W.6).
    !> The ends are given by their distances to the edges: d_lo = s + r >= 0 and
    !> d_hi = r - s >= 0 with d_lo + d_hi = 2 r (the caller forms the pair without
    !> cancellation, e.g. d_lo = 2 r - b, d_hi = b for the contact strip of width b at the
    !> s = +r edge). s_a <= s_b is expected; an empty or reversed strip gives m = 0.
    !> Circle: with the half angles phi = u/2 of u = acos(s/r) (cos phi = sqrt(d_lo/(2 r)),
    !> sin phi = sqrt(d_hi/(2 r))), delta = u_a - u_b = 2 atan2(2 r w/P, Q) and
    !> sin((u_a + u_b)/2) = P/(2 r), cos((u_a + u_b)/2) = (s_a + s_b)/Q, where w = s_b - s_a,
    !> P = sqrt(d_hi_a d_lo_b) + sqrt(d_lo_a d_hi_b), Q = sqrt(d_lo_a d_lo_b) +
    !> sqrt(d_hi_a d_hi_b); then (W.4)-(W.6) are sums of non-negative terms, except the
    !> second term of m2 for delta > pi/2 (a strip wider than a quarter turn), where at most
    !> a factor 2.3 (about one bit) cancels. Relative error a few ulps otherwise.
    !> alpha is ignored for the circle.
    pure subroutine strip_moments(footing, r, alpha, d_lo_a, d_hi_a, d_lo_b, d_hi_b, m)
        integer, intent(in) :: footing      !! FOOTING_CIRCLE or FOOTING_RECTANGLE
        real(dp), intent(in) :: r           !! radius or half-width (m), > 0
        real(dp), intent(in) :: alpha       !! half-length of the rectangle (m), > 0
        real(dp), intent(in) :: d_lo_a      !! s_a + r (m), >= 0
        real(dp), intent(in) :: d_hi_a      !! r - s_a (m), >= 0
        real(dp), intent(in) :: d_lo_b      !! s_b + r (m), >= 0
        real(dp), intent(in) :: d_hi_b      !! r - s_b (m), >= 0
        real(dp), intent(out) :: m(0:2)     !! m0 (m^2), m1 (m^3), m2 (m^4)
        real(dp) :: w, sa, sb, ssum, p, q, delta, sin_sig, cos_sig, ya, yb

        m = 0.0_dp
        ! width and end coordinates from the smaller distances (least absolute rounding)
        if (d_hi_a + d_hi_b <= d_lo_a + d_lo_b) then
            w = d_hi_a - d_hi_b
        else
            w = d_lo_b - d_lo_a
        end if
        if (.not. (w > 0.0_dp)) return
        sa = end_coordinate(r, d_lo_a, d_hi_a)
        sb = end_coordinate(r, d_lo_b, d_hi_b)
        ssum = sa + sb
        if (footing == FOOTING_RECTANGLE) then
            m(0) = 2.0_dp * alpha * w                                           ! (W.3)
            m(1) = alpha * w * ssum                                             ! (W.3)
            ! s_b^3 - s_a^3 = w (s_a^2 + s_a s_b + s_b^2) = w (3 (s_a + s_b)^2 + w^2)/4
            m(2) = alpha * w * (3.0_dp * ssum * ssum + w * w) / 6.0_dp          ! (W.3)
            return
        end if
        p = sqrt(d_hi_a * d_lo_b) + sqrt(d_lo_a * d_hi_b)
        q = sqrt(d_lo_a * d_lo_b) + sqrt(d_hi_a * d_hi_b)
        delta = 2.0_dp * atan2(2.0_dp * r * w / p, q)                           ! (W.2)
        sin_sig = p / (2.0_dp * r)
        ! m0 = r^2 [(2u - sin 2u)/2] = r^2 (delta - sin delta + 2 sin^2 sigma sin delta)
        m(0) = r * r * x_minus_sin(delta) + 0.5_dp * p * p * sin(delta)         ! (W.4)
        ! m1 = (2/3) (y_a^3 - y_b^3), y = sqrt(d_lo d_hi) = sqrt(r^2 - s^2), and
        ! y_a - y_b = (s_b^2 - s_a^2)/(y_a + y_b) = w (s_a + s_b)/(y_a + y_b)
        ya = sqrt(d_lo_a * d_hi_a)
        yb = sqrt(d_lo_b * d_hi_b)
        if (ya + yb > 0.0_dp) then
            m(1) = (2.0_dp / 3.0_dp) * w * ssum * ((ya * ya + ya * yb + yb * yb) &
                   / (ya + yb))                                                 ! (W.5)
        end if
        ! m2 = r^4 [(4u - sin 4u)/16] = (r^4/16) (2 (2 delta - sin 2 delta)
        !      + 4 sin(2 delta) sin^2(2 sigma)), sin 2 sigma = 2 sin sigma cos sigma
        if (q > 0.0_dp) then
            cos_sig = ssum / q
        else
            cos_sig = 0.0_dp      ! the whole diameter: sigma = pi/2
        end if
        m(2) = (r * r) * (r * r) / 16.0_dp * (2.0_dp * x_minus_sin(2.0_dp * delta) &
               + 16.0_dp * sin(2.0_dp * delta) * (sin_sig * cos_sig)**2)        ! (W.6)
    end subroutine strip_moments

    !> s (m) from the distances to the edges, d_lo = s + r and d_hi = r - s, through the
    !> smaller one (one rounding).
    pure function end_coordinate(r, d_lo, d_hi) result(s)
        real(dp), intent(in) :: r, d_lo, d_hi
        real(dp) :: s
        if (d_lo <= d_hi) then
            s = d_lo - r
        else
            s = r - d_hi
        end if
    end function end_coordinate

end module seispulse_winkler_contact
