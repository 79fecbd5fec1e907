!> Rigid cylinder and block on a rigid base (doc/cylinder.md): the identities of [AD11]
!> chapter 1 (J_o by the parallel-axis theorem, p in rad/s, Housner's restitution, the
!> pushover end points and normalized mid-points), hollow -> solid, a custom body equal to
!> the block bit for bit, Housner's free-rocking period with the cylinder's p, the
!> equivalences both ways, maps on both axis systems against the dimensionless map and
!> single runs, the overturning threshold against single runs, the corrections to the
!> printed source, and bad input. Every expected value is computed here independently.
module test_cylinder
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_negative_inf, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_pulses, only: pulse_t, pulse_accel, exponential_pulse, half_sine_pulse, &
                                sine_cycle_pulse, cosine_cycle_pulse, rectangular_pulse, &
                                triangular_pulse, ricker_pulse, pulse_end_time, ricker_window, &
                                PULSE_SINE_CYCLE, PULSE_RICKER, PULSE_EXPONENTIAL, &
                                PULSE_HALF_SINE, PULSE_MP
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, rectangular_block, &
                                     rock_pulse, overturning_map, ROCK_RUN_OVERTURN_NO_IMPACT, &
                                     ROCK_RUN_OVERTURN_ONE_IMPACT, ROCK_RUN_OVERTURN_MANY, &
                                     ROCK_RUN_TIME_LIMIT
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props, &
                                  body_rocking_block, equivalent_cylinder, equivalent_block, &
                                  rigid_pushover, normalized_pushover, body_overturning_map, &
                                  map_difference, overturning_threshold, BODY_SOLID_CYLINDER, &
                                  BODY_HOLLOW_CYLINDER, BODY_CUSTOM, BODY_BLOCK, &
                                  MAP_AXES_DIMENSIONLESS, MAP_AXES_DIMENSIONAL, MAP_DIFF_SAME, &
                                  MAP_DIFF_ONLY_FIRST, MAP_DIFF_ONLY_SECOND, MAP_DIFF_OTHER_MODE
    use seispulse_format, only: int_str
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_cylinder

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp

contains

    subroutine collect_cylinder(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('solid cylinder: J_o, p (rad/s), Res; h/r = 2 numbers', &
                              test_solid), &
                 new_unittest('hollow cylinder: tube = outer - inner; r_inner -> 0 is solid', &
                              test_hollow), &
                 new_unittest('block and custom J_o = 4/3 m R^2: same bits, same runs', &
                              test_custom_block), &
                 new_unittest('rigid pushover: F(0), M(0), M(theta_c), mid-points', &
                              test_pushover), &
                 new_unittest('free rocking e = 1: Housner period with the cylinder p', &
                              test_free_period), &
                 new_unittest('equivalent cylinder and block, both ways, round trips', &
                              test_equivalence), &
                 new_unittest('pulse peaks equal amp for every kind a map takes', &
                              test_pulse_peaks), &
                 new_unittest('maps: g-Hz axes = dimensionless map = single runs', test_maps), &
                 new_unittest('map_difference; cylinder vs block: no-impact cells agree', &
                              test_map_difference), &
                 new_unittest('overturning threshold: PGA overturns, PGA (1 - 1e-5) not', &
                              test_threshold), &
                 new_unittest('corrections: J_o, p in rad/s, Res floored at 0', &
                              test_corrections), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input)]
    end subroutine collect_cylinder

    ! ---------------------------------------------------------------- helpers

    !> A cylinder; fail unless the status is success.
    subroutine make_cylinder(error, r, h, mass, g, body, r_inner, j_o, j_axis)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: r, h, mass, g
        type(rocking_body_t), intent(out) :: body
        real(dp), intent(in), optional :: r_inner, j_o, j_axis
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call cylinder_props(r, h, mass, g, body, stat, msg, r_inner=r_inner, j_o=j_o, &
                            j_axis=j_axis)
        call check(error, stat, SEISPULSE_SUCCESS, 'cylinder_props: '//trim(msg))
    end subroutine make_cylinder

    logical function overturned(run)
        type(rocking_run_t), intent(in) :: run
        overturned = run%outcome == ROCK_RUN_OVERTURN_NO_IMPACT .or. &
                     run%outcome == ROCK_RUN_OVERTURN_ONE_IMPACT .or. &
                     run%outcome == ROCK_RUN_OVERTURN_MANY
    end function overturned

    !> Status is SEISPULSE_INVALID_INPUT and the message contains `part`.
    subroutine expect_bad(error, stat, msg, part)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg, part
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'status for '//part)
        if (allocated(error)) return
        call check(error, index(msg, part) > 0, 'message "'//trim(msg)//'" names '//part)
    end subroutine expect_bad

    ! ---------------------------------------------------------------- tests

    !> doc/cylinder.md (Y.1)-(Y.7), (Y.11): the parallel-axis sum, p = sqrt(m g R/J_o),
    !> Res = 1 - 24 r^2/(15 r^2 + 16 h^2); h/r = 2: J_o/(m r^2) = 79/12 = 6.5833..,
    !> Res = 55/79 = 0.6962.., p = 1.825 rad/s for r = 1 m, g = 9.81 m/s^2 ([AD11] p.12-13).
    subroutine test_solid(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        real(dp) :: r, h, m, g, big_r, jo, rs(2), hs(2), ms(2)
        integer :: k
        rs = [1.0_dp, 0.37_dp]
        hs = [2.0_dp, 2.9_dp]
        ms = [1.0_dp, 1234.5_dp]
        do k = 1, 2
            r = rs(k)
            h = hs(k)
            m = ms(k)
            g = 9.81_dp
            call make_cylinder(error, r, h, m, g, c)
            if (allocated(error)) return
            call check(error, c%shape, BODY_SOLID_CYLINDER, 'shape')
            if (allocated(error)) return
            big_r = sqrt(r * r + h * h)
            ! parallel axes: J_G of a solid cylinder of length 2h about a diameter + m R^2
            jo = m * (3.0_dp * r * r + (2.0_dp * h)**2) / 12.0_dp + m * big_r**2
            call check(error, c%j_o, jo, rtol=2.0e-16_dp, message='J_o parallel-axis sum')
            if (allocated(error)) return
            call check(error, c%j_o, 1.25_dp * m * r * r + 4.0_dp / 3.0_dp * m * h * h, &
                       rtol=4.0e-16_dp, message='J_o = 5/4 m r^2 + 4/3 m h^2')
            if (allocated(error)) return
            call check(error, c%j_g, jo - m * big_r**2, rtol=1.0e-15_dp, message='J_G')
            if (allocated(error)) return
            call check(error, c%j_axis, 0.5_dp * m * r * r, rtol=1.0e-15_dp, message='J_axis')
            if (allocated(error)) return
            call check(error, c%theta_c, atan(r / h), rtol=1.0e-15_dp, message='theta_c')
            if (allocated(error)) return
            call check(error, c%big_r, big_r, rtol=1.0e-15_dp, message='R')
            if (allocated(error)) return
            call check(error, c%p, sqrt(m * g * big_r / jo), rtol=1.0e-15_dp, &
                       message='p = sqrt(m g R/J_o)')
            if (allocated(error)) return
            call check(error, c%e, 1.0_dp - 24.0_dp * r * r / (15.0_dp * r * r + 16.0_dp * h * h), &
                       rtol=1.0e-15_dp, message='Res closed form')
            if (allocated(error)) return
            call check(error, c%e, 1.0_dp - 2.0_dp * m * big_r**2 / jo * (r / big_r)**2, &
                       rtol=1.0e-15_dp, message='Res = 1 - (2 m R^2/J_o) sin^2 theta_c')
            if (allocated(error)) return
            call check(error, c%weight, m * g, rtol=1.0e-15_dp, message='W')
            if (allocated(error)) return
            call check(error, c%m_max, m * g * r, rtol=1.0e-15_dp, message='M_max = m g r')
            if (allocated(error)) return
            call check(error, c%f_uplift, m * g * r / h, rtol=1.0e-15_dp, message='W r/h')
            if (allocated(error)) return
        end do
        ! the numbers of h/r = 2 at r = 1 m, m = 1 kg, g = 9.81 m/s^2
        call make_cylinder(error, 1.0_dp, 2.0_dp, 1.0_dp, 9.81_dp, c)
        if (allocated(error)) return
        call check(error, c%j_o, 79.0_dp / 12.0_dp, rtol=2.0e-16_dp, message='79/12')
        if (allocated(error)) return
        call check(error, nint(c%j_o * 1.0e4_dp), 65833, 'J_o/(m r^2) = 6.5833')
        if (allocated(error)) return
        call check(error, c%e, 55.0_dp / 79.0_dp, rtol=1.0e-15_dp, message='Res = 55/79')
        if (allocated(error)) return
        call check(error, nint(c%e * 1.0e4_dp), 6962, 'Res = 0.6962')
        if (allocated(error)) return
        call check(error, nint(c%p * 1.0e3_dp), 1825, 'p = 1.825 rad/s')
    end subroutine test_solid

    !> Hollow cylinder (Y.4): a tube is the solid of radius r minus the solid of radius
    !> r_inner, masses in proportion to the areas; r_inner -> 0 gives the solid cylinder.
    subroutine test_hollow(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c, s
        real(dp) :: r, ri, h, m, mo, mi, jg, jax
        r = 0.8_dp
        h = 2.1_dp
        m = 700.0_dp
        ri = 0.6_dp * r
        call make_cylinder(error, r, h, m, g0, c, r_inner=ri)
        if (allocated(error)) return
        call check(error, c%shape, BODY_HOLLOW_CYLINDER, 'shape')
        if (allocated(error)) return
        mo = m * r * r / (r * r - ri * ri)
        mi = m * ri * ri / (r * r - ri * ri)
        jg = mo * (3.0_dp * r * r + 4.0_dp * h * h) / 12.0_dp &
             - mi * (3.0_dp * ri * ri + 4.0_dp * h * h) / 12.0_dp
        jax = 0.5_dp * mo * r * r - 0.5_dp * mi * ri * ri
        call check(error, c%j_g, jg, rtol=1.0e-14_dp, message='J_G outer - inner')
        if (allocated(error)) return
        call check(error, c%j_o, jg + m * (r * r + h * h), rtol=1.0e-14_dp, message='J_o')
        if (allocated(error)) return
        call check(error, c%j_axis, jax, rtol=1.0e-14_dp, message='J_axis outer - inner')
        if (allocated(error)) return
        call check(error, c%p, sqrt(m * g0 * sqrt(r * r + h * h) / c%j_o), rtol=1.0e-15_dp, &
                   message='p')
        if (allocated(error)) return
        ! a hollow cylinder has more inertia: lower p, higher e than the solid one
        call make_cylinder(error, r, h, m, g0, s)
        if (allocated(error)) return
        call check(error, c%p < s%p .and. c%e > s%e, 'hollow: p lower, e higher')
        if (allocated(error)) return
        ! limit r_inner -> 0
        call make_cylinder(error, r, h, m, g0, c, r_inner=1.0e-9_dp * r)
        if (allocated(error)) return
        call check(error, c%j_o, s%j_o, rtol=1.0e-15_dp, message='r_inner -> 0: J_o')
        if (allocated(error)) return
        call check(error, c%p, s%p, rtol=1.0e-15_dp, message='r_inner -> 0: p')
        if (allocated(error)) return
        call check(error, c%e, s%e, rtol=1.0e-15_dp, message='r_inner -> 0: e')
        if (allocated(error)) return
        call make_cylinder(error, r, h, m, g0, c, r_inner=0.0_dp)
        if (allocated(error)) return
        call check(error, c%shape, BODY_SOLID_CYLINDER, 'r_inner = 0 is the solid cylinder')
        if (allocated(error)) return
        call check(error, same_bits(c%j_o, s%j_o) .and. same_bits(c%p, s%p), &
                   'r_inner = 0: same bits as the solid cylinder')
    end subroutine test_hollow

    !> A custom body with J_o = 4/3 m R^2 (m = 3 kg, b = 3 m, h = 4 m: J_o = 100 exactly) is
    !> the uniform block: the same p and e as block_props and rectangular_block, bit for
    !> bit, and bit-identical rock_pulse runs.
    subroutine test_custom_block(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c, b
        type(rocking_block_t) :: bc, bb, br
        type(rocking_run_t) :: rc, rr
        type(pulse_t) :: pl
        integer :: stat, k
        character(len=200) :: msg
        call make_cylinder(error, 3.0_dp, 4.0_dp, 3.0_dp, g0, c, j_o=100.0_dp, j_axis=7.0_dp)
        if (allocated(error)) return
        call check(error, c%shape, BODY_CUSTOM, 'shape custom')
        if (allocated(error)) return
        call check(error, c%j_axis, 7.0_dp, message='j_axis kept')
        if (allocated(error)) return
        call check(error, c%j_g, 25.0_dp, message='J_G = J_o - m R^2')
        if (allocated(error)) return
        call block_props(3.0_dp, 4.0_dp, 3.0_dp, g0, b, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'block_props '//trim(msg))
        if (allocated(error)) return
        call check(error, b%shape, BODY_BLOCK, 'shape block')
        if (allocated(error)) return
        call check(error, ieee_is_nan(b%j_axis), 'block j_axis NaN')
        if (allocated(error)) return
        call check(error, b%j_o, 100.0_dp, rtol=2.0e-16_dp, message='block J_o = 4/3 m R^2')
        if (allocated(error)) return
        call check(error, b%j_g, 25.0_dp, rtol=2.0e-16_dp, message='block J_G = m(b^2+h^2)/3')
        if (allocated(error)) return
        call check(error, b%p, sqrt(3.0_dp * g0 / (4.0_dp * 5.0_dp)), rtol=2.0e-16_dp, &
                   message='block p = sqrt(3 g/(4 R))')
        if (allocated(error)) return
        call check(error, b%e, 1.0_dp - 1.5_dp * 0.36_dp, rtol=1.0e-15_dp, &
                   message='block e = 1 - 1.5 sin^2')
        if (allocated(error)) return
        call rectangular_block(3.0_dp, 4.0_dp, g0, br, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'rectangular_block')
        if (allocated(error)) return
        call body_rocking_block(c, bc, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'body_rocking_block custom '//trim(msg))
        if (allocated(error)) return
        call body_rocking_block(b, bb, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'body_rocking_block block '//trim(msg))
        if (allocated(error)) return
        call check(error, same_bits(c%p, br%p) .and. same_bits(c%e, br%e) .and. &
                   same_bits(b%p, br%p) .and. same_bits(b%e, br%e), 'props: same p, e bits')
        if (allocated(error)) return
        call check(error, same_bits(bc%p, br%p) .and. same_bits(bc%e, br%e) .and. &
                   same_bits(bc%alpha, br%alpha) .and. same_bits(bb%p, br%p) .and. &
                   same_bits(bb%alpha, br%alpha) .and. same_bits(bb%e, br%e), &
                   'rocking blocks: same bits')
        if (allocated(error)) return
        ! a one-sine pulse that rocks the block with impacts (5 periods of a free run)
        pl = sine_cycle_pulse(1.2_dp * g0 * 0.75_dp, 1.5_dp)
        call rock_pulse(bc, pl, rc, stat, msg, t_max=20.0_dp)
        call check(error, stat, SEISPULSE_SUCCESS, 'rock_pulse custom '//trim(msg))
        if (allocated(error)) return
        call rock_pulse(br, pl, rr, stat, msg, t_max=20.0_dp)
        call check(error, stat, SEISPULSE_SUCCESS, 'rock_pulse block '//trim(msg))
        if (allocated(error)) return
        call check(error, rc%n_impacts > 0, 'the run has impacts')
        if (allocated(error)) return
        call check(error, rc%outcome, rr%outcome, 'same outcome')
        if (allocated(error)) return
        call check(error, rc%n_impacts, rr%n_impacts, 'same impacts')
        if (allocated(error)) return
        call check(error, rc%n_steps, rr%n_steps, 'same steps')
        if (allocated(error)) return
        call check(error, same_bits(rc%t_uplift, rr%t_uplift) .and. &
                   same_bits(rc%theta_max, rr%theta_max) .and. &
                   same_bits(rc%theta_min, rr%theta_min) .and. &
                   same_bits(rc%t_end, rr%t_end), 'bit-identical run')
        if (allocated(error)) return
        do k = 1, rc%n_impacts
            call check(error, same_bits(rc%t_impacts(k), rr%t_impacts(k)), 'impact times bits')
            if (allocated(error)) return
        end do
    end subroutine test_custom_block

    !> (Y.10)-(Y.12): F = W tan(theta_c - theta), M = W (r cos theta - h sin theta); F(0) = W r/h,
    !> M(0) = m g r, M(theta_c) = 0; M/(m g r) at theta_c/2 is 1/(2 cos(theta_c/2)):
    !> 0.514, 0.541, 0.588 for h/r = 2, 1, 0.5.
    subroutine test_pushover(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        real(dp) :: f, mo, r, h, m, w, th, hr(3), mid
        logical :: st
        integer :: stat, k, expect(3)
        character(len=200) :: msg
        r = 0.6_dp
        h = 1.9_dp
        m = 250.0_dp
        call make_cylinder(error, r, h, m, g0, c)
        if (allocated(error)) return
        w = m * g0
        call rigid_pushover(c, 0.0_dp, f, mo, st, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'pushover '//trim(msg))
        if (allocated(error)) return
        call check(error, f, w * r / h, rtol=1.0e-15_dp, message='F(0) = W r/h')
        if (allocated(error)) return
        call check(error, mo, m * g0 * r, rtol=1.0e-15_dp, message='M(0) = m g r')
        if (allocated(error)) return
        call check(error, st, 'stable at 0')
        if (allocated(error)) return
        call rigid_pushover(c, c%theta_c, f, mo, st, stat, msg)
        call check(error, mo, 0.0_dp, atol=0.0_dp, message='M(theta_c) = 0')
        if (allocated(error)) return
        call check(error, f, 0.0_dp, atol=0.0_dp, message='F(theta_c) = 0')
        if (allocated(error)) return
        call check(error, st, 'stable at theta_c')
        if (allocated(error)) return
        do k = 1, 5
            th = 0.25_dp * real(k, dp) * c%theta_c + 0.01_dp
            call rigid_pushover(c, th, f, mo, st, stat, msg)
            call check(error, mo, w * (r * cos(th) - h * sin(th)), rtol=1.0e-13_dp, &
                       atol=1.0e-13_dp * w * r, message='M = W (r cos - h sin)')
            if (allocated(error)) return
            ! moment of the couple: F times the height of the CoM above the pivot
            call check(error, mo, f * (h * cos(th) + r * sin(th)), rtol=1.0e-13_dp, &
                       atol=1.0e-13_dp * w * r, message='M = F (h cos + r sin)')
            if (allocated(error)) return
            call check(error, st .eqv. th <= c%theta_c, 'stable iff theta <= theta_c')
            if (allocated(error)) return
            call check(error, (f < 0.0_dp) .eqv. (th > c%theta_c), 'F < 0 beyond theta_c')
            if (allocated(error)) return
            call rigid_pushover(c, -th, f, mo, st, stat, msg)
            call check(error, mo, -w * (r * cos(th) - h * sin(th)), rtol=1.0e-13_dp, &
                       atol=1.0e-13_dp * w * r, message='mirror image')
            if (allocated(error)) return
        end do
        call rigid_pushover(c, 0.5_dp * pi, f, mo, st, stat, msg)
        call check(error, mo, -w * h, rtol=1.0e-14_dp, message='M(pi/2) = -W h')
        if (allocated(error)) return
        call check(error, .not. st, 'unstable at pi/2')
        if (allocated(error)) return
        ! normalized curve and the mid-points
        hr = [2.0_dp, 1.0_dp, 0.5_dp]
        expect = [514, 541, 588]
        do k = 1, 3
            call make_cylinder(error, 1.0_dp, hr(k), 10.0_dp, g0, c)
            if (allocated(error)) return
            mid = 1.0_dp / (2.0_dp * cos(0.5_dp * atan(1.0_dp / hr(k))))
            call check(error, normalized_pushover(c%theta_c, 0.5_dp), mid, rtol=1.0e-15_dp, &
                       message='mid-point closed form')
            if (allocated(error)) return
            call check(error, nint(1000.0_dp * mid), expect(k), 'mid-point to 3 digits')
            if (allocated(error)) return
            call rigid_pushover(c, 0.5_dp * c%theta_c, f, mo, st, stat, msg)
            call check(error, mo / c%m_max, mid, rtol=1.0e-14_dp, message='M/(m g r) at u = 1/2')
            if (allocated(error)) return
            call check(error, normalized_pushover(c%theta_c, 0.0_dp), 1.0_dp, &
                       rtol=1.0e-15_dp, message='(0, 1)')
            if (allocated(error)) return
            call check(error, normalized_pushover(c%theta_c, 1.0_dp), 0.0_dp, atol=0.0_dp, &
                       message='(1, 0)')
            if (allocated(error)) return
        end do
        ! squatter bodies bulge more: the mid-point grows as h/r falls
        call check(error, normalized_pushover(atan(2.0_dp), 0.5_dp) > &
                   normalized_pushover(atan(0.5_dp), 0.5_dp), 'more convex when squat')
    end subroutine test_pushover

    !> Housner [H63]: free rocking of the linearized model from theta0 at rest, e = 1, has
    !> the period T = (4/p) acosh(1/(1 - theta0/theta_c)) = (4/p) artanh(sqrt(1 - (1 -
    !> theta0/theta_c)^2)); impacts at T/4 + (k - 1) T/2, with p in rad/s.
    subroutine test_free_period(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        real(dp) :: th0, q, tp, tp2, p
        integer :: stat, k
        character(len=200) :: msg
        call make_cylinder(error, 0.3_dp, 1.7_dp, 900.0_dp, g0, c)
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg, e=1.0_dp, linearized=.true.)
        call check(error, stat, SEISPULSE_SUCCESS, 'block '//trim(msg))
        if (allocated(error)) return
        p = sqrt(900.0_dp * g0 * sqrt(0.3_dp**2 + 1.7_dp**2) &
                 / (900.0_dp * (1.25_dp * 0.09_dp + 4.0_dp / 3.0_dp * 1.7_dp**2)))
        th0 = 0.4_dp * c%theta_c
        q = 1.0_dp - th0 / c%theta_c
        tp = 4.0_dp / p * log((1.0_dp + sqrt(1.0_dp - q * q)) / q)       ! acosh(1/q)
        tp2 = 4.0_dp / p * 0.5_dp * log((1.0_dp + sqrt(1.0_dp - q * q)) &
                                         / (1.0_dp - sqrt(1.0_dp - q * q)))  ! artanh form
        call check(error, tp2, tp, rtol=1.0e-13_dp, message='two forms of the period')
        if (allocated(error)) return
        call rock_pulse(blk, rectangular_pulse(0.0_dp, 1.0_dp), run, stat, msg, &
                        t_max=12.0_dp * tp, theta0=th0)
        call check(error, stat, SEISPULSE_SUCCESS, 'rock_pulse '//trim(msg))
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_TIME_LIMIT, 'rocks for ever')
        if (allocated(error)) return
        call check(error, run%n_impacts >= 20, 'many impacts')
        if (allocated(error)) return
        do k = 1, run%n_impacts
            call check(error, run%t_impacts(k), tp / 4.0_dp + real(k - 1, dp) * tp / 2.0_dp, &
                       rtol=1.0e-10_dp, message='impact times of Housner period')
            if (allocated(error)) return
        end do
    end subroutine test_free_period

    !> (Y.13)-(Y.15): same p, same M_max; block -> cylinder -> block and cylinder -> block ->
    !> cylinder give the body back; a stated theta_c or alpha is kept.
    subroutine test_equivalence(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b, c, b2, c2, c0
        real(dp) :: big_r, s
        integer :: stat
        character(len=200) :: msg
        call block_props(0.35_dp, 1.4_dp, 520.0_dp, g0, b, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'block '//trim(msg))
        if (allocated(error)) return
        call equivalent_cylinder(b, c, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'equivalent_cylinder '//trim(msg))
        if (allocated(error)) return
        call check(error, c%shape, BODY_SOLID_CYLINDER, 'a solid cylinder')
        if (allocated(error)) return
        call check(error, c%p, b%p, rtol=1.0e-14_dp, message='same p')
        if (allocated(error)) return
        call check(error, c%m_max, b%m_max, rtol=1.0e-14_dp, message='same M_max')
        if (allocated(error)) return
        call check(error, c%mass * c%r, b%mass * b%r, rtol=1.0e-14_dp, message='m_c r = m_b b')
        if (allocated(error)) return
        call check(error, c%theta_c, b%theta_c, rtol=1.0e-14_dp, message='same slenderness')
        if (allocated(error)) return
        ! R from p with J_o/(m R^2) of the solid cylinder, evaluated from its own formula
        s = sin(b%theta_c)
        big_r = g0 / (b%p**2 * (1.25_dp * s * s + 4.0_dp / 3.0_dp * (1.0_dp - s * s)))
        call check(error, c%big_r, big_r, rtol=1.0e-14_dp, message='R_c')
        if (allocated(error)) return
        call equivalent_block(c, b2, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'equivalent_block '//trim(msg))
        if (allocated(error)) return
        call check(error, b2%r, b%r, rtol=1.0e-14_dp, message='round trip b')
        if (allocated(error)) return
        call check(error, b2%h, b%h, rtol=1.0e-14_dp, message='round trip h')
        if (allocated(error)) return
        call check(error, b2%mass, b%mass, rtol=1.0e-14_dp, message='round trip mass')
        if (allocated(error)) return
        ! a stated slenderness
        call equivalent_cylinder(b, c, stat, msg, theta_c=0.4_dp)
        call check(error, stat, SEISPULSE_SUCCESS, 'theta_c given '//trim(msg))
        if (allocated(error)) return
        call check(error, c%theta_c, 0.4_dp, rtol=1.0e-15_dp, message='theta_c kept')
        if (allocated(error)) return
        call check(error, c%p, b%p, rtol=1.0e-14_dp, message='same p (theta_c given)')
        if (allocated(error)) return
        call check(error, c%m_max, b%m_max, rtol=1.0e-14_dp, message='same M_max (theta_c)')
        if (allocated(error)) return
        ! cylinder -> block -> cylinder, and a stated alpha
        call make_cylinder(error, 0.45_dp, 1.3_dp, 800.0_dp, g0, c0)
        if (allocated(error)) return
        call equivalent_block(c0, b, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'equivalent_block '//trim(msg))
        if (allocated(error)) return
        call check(error, b%big_r, 0.75_dp * g0 / c0%p**2, rtol=1.0e-14_dp, &
                   message='R_b = 3 g/(4 p^2)')
        if (allocated(error)) return
        call check(error, b%m_max, c0%m_max, rtol=1.0e-14_dp, message='block M_max')
        if (allocated(error)) return
        call equivalent_cylinder(b, c2, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'back '//trim(msg))
        if (allocated(error)) return
        call check(error, c2%r, c0%r, rtol=1.0e-14_dp, message='round trip r')
        if (allocated(error)) return
        call check(error, c2%h, c0%h, rtol=1.0e-14_dp, message='round trip h')
        if (allocated(error)) return
        call check(error, c2%mass, c0%mass, rtol=1.0e-14_dp, message='round trip m')
        if (allocated(error)) return
        call equivalent_block(c0, b, stat, msg, alpha=0.2_dp)
        call check(error, b%theta_c, 0.2_dp, rtol=1.0e-15_dp, message='alpha kept')
        if (allocated(error)) return
        call check(error, b%p, c0%p, rtol=1.0e-14_dp, message='same p (alpha given)')
        if (allocated(error)) return
        call check(error, b%m_max, c0%m_max, rtol=1.0e-14_dp, message='same M_max (alpha)')
        if (allocated(error)) return
        ! a hollow cylinder's equivalent block
        call make_cylinder(error, 0.45_dp, 1.3_dp, 800.0_dp, g0, c0, r_inner=0.3_dp)
        if (allocated(error)) return
        call equivalent_block(c0, b, stat, msg)
        call check(error, b%p, c0%p, rtol=1.0e-14_dp, message='hollow: same p')
    end subroutine test_equivalence

    !> The map's PGA axis is the pulse's amp: sampled |a_g| peaks at amp for every kind the
    !> map takes (exponential of several beta, half and full; Ricker with t0 = 0 and 1.5/f_p).
    subroutine test_pulse_peaks(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: npl = 12, ns = 40001
        type(pulse_t) :: pls(npl)
        real(dp) :: te, amax, t, tol
        integer :: k, i
        pls = [exponential_pulse(2.0_dp, 1.0_dp, 0.0_dp, .false.), &
               exponential_pulse(2.0_dp, 1.0_dp, -6.0_dp, .false.), &
               exponential_pulse(2.0_dp, 1.0_dp, 9.0_dp, .true.), &
               exponential_pulse(2.0_dp, 1.0_dp, ieee_value(1.0_dp, ieee_negative_inf), &
                                 .false.), &
               half_sine_pulse(2.0_dp, 1.0_dp), sine_cycle_pulse(2.0_dp, 1.0_dp), &
               cosine_cycle_pulse(2.0_dp, 1.0_dp), rectangular_pulse(2.0_dp, 1.0_dp), &
               triangular_pulse(2.0_dp, 1.0_dp, 0.3_dp), &
               triangular_pulse(2.0_dp, 1.0_dp, 1.0_dp), &
               ricker_pulse(2.0_dp, 1.0_dp, 0.0_dp), ricker_pulse(2.0_dp, 1.0_dp, 1.5_dp)]
        do k = 1, npl
            if (pls(k)%kind == PULSE_RICKER) then
                call ricker_window(pls(k), t, te)   ! the end of the support (s)
            else
                te = pulse_end_time(pls(k))
            end if
            amax = 0.0_dp
            do i = 0, ns - 1
                t = te * real(i, dp) / real(ns - 1, dp)
                amax = max(amax, abs(pulse_accel(pls(k), t)))
            end do
            call check(error, amax <= 2.0_dp * (1.0_dp + 1.0e-14_dp), 'peak <= amp')
            if (allocated(error)) return
            ! peak_frac = 1 (k = 10): the peak is the left limit at t = T (a(T) = 0), so the
            ! samples reach 2 (1 - 1/(ns - 1)) only
            tol = 1.0e-6_dp
            if (k == 10) tol = 1.01_dp / real(ns - 1, dp)
            call check(error, amax, 2.0_dp, rtol=tol, message='sampled peak = amp, pulse ' &
                       //int_str(k))
            if (allocated(error)) return
        end do
    end subroutine test_pulse_peaks

    !> A map in g-Hz axes equals the dimensionless map (overturning_map) at omega_p/p =
    !> 2 pi f_p/p, a_p/(g tan theta_c) = PGA/tan(theta_c), and single SI runs of the body.
    subroutine test_maps(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: tmpl, pl
        integer, parameter :: nx = 3, ny = 4
        real(dp) :: fx(nx), py(ny), xr(nx), yr(ny)
        integer :: cd(ny, nx), cn(ny, nx), cref(ny, nx), stat, kinds(3), kk, i, j
        character(len=200) :: msg
        logical :: any_over, any_safe
        call make_cylinder(error, 0.5_dp, 1.5_dp, 2000.0_dp, g0, c)
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'block '//trim(msg))
        if (allocated(error)) return
        fx = [0.8_dp, 1.6_dp, 3.0_dp]
        py = [0.3_dp, 0.6_dp, 1.0_dp, 1.6_dp]
        xr = 2.0_dp * pi * fx / c%p
        yr = py / tan(c%theta_c)
        kinds = [PULSE_SINE_CYCLE, PULSE_RICKER, PULSE_EXPONENTIAL]
        any_over = .false.
        any_safe = .false.
        do kk = 1, 3
            tmpl = exponential_pulse(1.0_dp, 1.0_dp, 2.0_dp, .true.)
            tmpl%kind = kinds(kk)
            call body_overturning_map(c, kinds(kk), fx, py, MAP_AXES_DIMENSIONAL, cd, stat, &
                                      msg, template=tmpl)
            call check(error, stat, SEISPULSE_SUCCESS, 'dimensional map '//trim(msg))
            if (allocated(error)) return
            call body_overturning_map(c, kinds(kk), xr, yr, MAP_AXES_DIMENSIONLESS, cn, stat, &
                                      msg, template=tmpl)
            call check(error, stat, SEISPULSE_SUCCESS, 'dimensionless map '//trim(msg))
            if (allocated(error)) return
            call overturning_map(c%theta_c, c%e, kinds(kk), xr, yr, cref, stat, msg, &
                                 template=tmpl)
            call check(error, stat, SEISPULSE_SUCCESS, 'overturning_map '//trim(msg))
            if (allocated(error)) return
            call check(error, all(cd == cref) .and. all(cn == cref), 'maps agree')
            if (allocated(error)) return
            any_over = any_over .or. any(cd > 0)
            any_safe = any_safe .or. any(cd == 0)
            ! single SI runs: the pulse of frequency f_p (Hz) and peak PGA g
            do j = 1, nx
                do i = 1, ny
                    select case (kinds(kk))
                    case (PULSE_SINE_CYCLE)
                        pl = sine_cycle_pulse(py(i) * g0, 1.0_dp / fx(j))
                    case (PULSE_RICKER)
                        pl = ricker_pulse(py(i) * g0, fx(j), 1.5_dp / fx(j))
                    case default
                        pl = exponential_pulse(py(i) * g0, 1.0_dp / fx(j), 2.0_dp, .true.)
                    end select
                    call rock_pulse(blk, pl, run, stat, msg)
                    call check(error, stat, SEISPULSE_SUCCESS, 'run '//trim(msg))
                    if (allocated(error)) return
                    call check(error, overturned(run) .eqv. cd(i, j) > 0, &
                               'single run agrees with the map cell')
                    if (allocated(error)) return
                end do
            end do
        end do
        call check(error, any_over .and. any_safe, 'the grid has both classes')
    end subroutine test_maps

    !> map_difference codes; a cylinder and a block of the same p and slenderness differ only
    !> in e, which acts at impacts: cells that overturn without impact (class 1) agree.
    subroutine test_map_difference(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c, b
        integer :: a1(2, 3), b1(2, 3), d(2, 3), stat, i, j
        integer, parameter :: nx = 5, ny = 5
        integer :: cc(ny, nx), cb(ny, nx), dd(ny, nx)
        real(dp) :: xr(nx), yr(ny)
        character(len=200) :: msg
        a1 = reshape([0, 1, 2, 3, -1, 2], [2, 3])
        b1 = reshape([0, 0, 2, 1, 0, 0], [2, 3])
        call map_difference(a1, b1, d, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'map_difference '//trim(msg))
        if (allocated(error)) return
        call check(error, all(d == reshape([MAP_DIFF_SAME, MAP_DIFF_ONLY_FIRST, &
                                            MAP_DIFF_SAME, MAP_DIFF_OTHER_MODE, -1, &
                                            MAP_DIFF_ONLY_FIRST], [2, 3])), 'codes')
        if (allocated(error)) return
        call map_difference(b1, a1, d, stat, msg)
        call check(error, d(2, 1), MAP_DIFF_ONLY_SECOND, 'only the second')
        if (allocated(error)) return
        call make_cylinder(error, 0.4_dp, 1.6_dp, 100.0_dp, g0, c)
        if (allocated(error)) return
        call equivalent_block(c, b, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'equivalent_block '//trim(msg))
        if (allocated(error)) return
        call check(error, abs(c%e - b%e) > 1.0e-4_dp, 'the two e differ')
        if (allocated(error)) return
        do j = 1, nx
            xr(j) = 1.0_dp + 1.5_dp * real(j - 1, dp)
        end do
        do i = 1, ny
            yr(i) = 1.5_dp + 1.0_dp * real(i - 1, dp)
        end do
        call body_overturning_map(c, PULSE_SINE_CYCLE, xr, yr, MAP_AXES_DIMENSIONLESS, cc, &
                                  stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'cylinder map '//trim(msg))
        if (allocated(error)) return
        call body_overturning_map(b, PULSE_SINE_CYCLE, xr, yr, MAP_AXES_DIMENSIONLESS, cb, &
                                  stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'block map '//trim(msg))
        if (allocated(error)) return
        call map_difference(cc, cb, dd, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'difference '//trim(msg))
        if (allocated(error)) return
        call check(error, any(cc == 1) .and. any(cc == 0), 'map has class 1 and safe cells')
        if (allocated(error)) return
        call check(error, all((cc == 1) .eqv. (cb == 1)), 'no-impact cells agree')
        if (allocated(error)) return
        call check(error, all(pack(dd, cc == 1) == MAP_DIFF_SAME), 'diff SAME there')
    end subroutine test_map_difference

    !> The threshold overturns and (1 - 1e-5) of it does not (single SI runs of the body under
    !> the one-sine pulse); +inf when the scan tops out below every overturning amplitude.
    subroutine test_threshold(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        real(dp) :: f(2), pga(2), a
        integer :: stat, k
        character(len=200) :: msg
        call make_cylinder(error, 0.5_dp, 1.5_dp, 2000.0_dp, g0, c)
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'block '//trim(msg))
        if (allocated(error)) return
        ! omega_p/p = 3 and 5
        f = [3.0_dp, 5.0_dp] * c%p / (2.0_dp * pi)
        call overturning_threshold(c, PULSE_SINE_CYCLE, f, pga, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'threshold '//trim(msg))
        if (allocated(error)) return
        do k = 1, 2
            call check(error, pga(k) > tan(c%theta_c) .and. pga(k) < 20.0_dp * tan(c%theta_c), &
                       'threshold inside the scan')
            if (allocated(error)) return
            call rock_pulse(blk, sine_cycle_pulse(pga(k) * g0, 1.0_dp / f(k)), run, stat, msg)
            call check(error, overturned(run), 'the threshold PGA overturns')
            if (allocated(error)) return
            a = pga(k) * (1.0_dp - 1.0e-5_dp)
            call rock_pulse(blk, sine_cycle_pulse(a * g0, 1.0_dp / f(k)), run, stat, msg)
            call check(error, .not. overturned(run), 'PGA (1 - 1e-5) does not overturn')
            if (allocated(error)) return
        end do
        ! a higher frequency needs a larger PGA
        call check(error, pga(2) > pga(1), 'threshold grows with frequency')
        if (allocated(error)) return
        ! the linearized model with e = 0.5 (both options reach the runs)
        call overturning_threshold(c, PULSE_SINE_CYCLE, f(1:1), pga(1:1), stat, msg, e=0.5_dp, &
                                   linearized=.true.)
        call check(error, stat, SEISPULSE_SUCCESS, 'linearized threshold '//trim(msg))
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg, e=0.5_dp, linearized=.true.)
        call check(error, blk%linearized .and. abs(blk%e - 0.5_dp) <= 0.0_dp, 'options kept')
        if (allocated(error)) return
        call rock_pulse(blk, sine_cycle_pulse(pga(1) * g0, 1.0_dp / f(1)), run, stat, msg)
        call check(error, overturned(run), 'linearized: the threshold PGA overturns')
        if (allocated(error)) return
        a = pga(1) * (1.0_dp - 1.0e-5_dp)
        call rock_pulse(blk, sine_cycle_pulse(a * g0, 1.0_dp / f(1)), run, stat, msg)
        call check(error, .not. overturned(run), 'linearized: PGA (1 - 1e-5) does not')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_SINE_CYCLE, f(1:1), pga(1:1), stat, msg, &
                                   pga_max_g=1.05_dp * tan(c%theta_c), n_scan=5)
        call check(error, stat, SEISPULSE_SUCCESS, 'low top '//trim(msg))
        if (allocated(error)) return
        call check(error, pga(1), ieee_value(1.0_dp, ieee_positive_inf), &
                   message='nothing overturns: +inf')
    end subroutine test_threshold

    !> doc/cylinder.md, Corrections to the printed source: each at a point where the printed
    !> reading differs. 1. J_o = m(h^2 + r^2) + (3 m r^2 + 4 m h^2)/12, not the transcript's
    !> (m r^2 + 4 m h^2)/12 term (6.4167 m r^2 at h/r = 2 instead of 6.5833). 2. p is rad/s:
    !> the period test above and p = 1.825 (not 1.825/(2 pi) = 0.2905). 3. Res squared sine,
    !> floored at 0: negative for h/r < 3/4 as printed, 0 here; at h/r = 2 the unsquared
    !> reading gives 0.3206, not 0.6962.
    subroutine test_corrections(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c
        type(rocking_block_t) :: blk
        real(dp) :: printed
        integer :: stat
        character(len=200) :: msg
        call make_cylinder(error, 1.0_dp, 2.0_dp, 1.0_dp, 9.81_dp, c)
        if (allocated(error)) return
        printed = 5.0_dp + 17.0_dp / 12.0_dp
        call check(error, abs(c%j_o - printed) > 0.1_dp, 'J_o is not the garbled reading')
        if (allocated(error)) return
        call check(error, abs(c%p - 1.82538_dp) < 1.0e-5_dp, 'p = 1.82538 rad/s')
        if (allocated(error)) return
        printed = 1.0_dp - 2.0_dp * 5.0_dp / c%j_o * sin(c%theta_c)
        call check(error, abs(c%e - printed) > 0.3_dp, 'Res has sin^2')
        if (allocated(error)) return
        ! h/r = 0.5: 1 - 24 r^2/(15 r^2 + 16 h^2) = 1 - 24/19 < 0
        call make_cylinder(error, 1.0_dp, 0.5_dp, 1.0_dp, 9.81_dp, c)
        if (allocated(error)) return
        ! the unfloored formula, from this body's own J_o, R and theta_c, is negative here
        printed = 1.0_dp - 2.0_dp * c%mass * c%big_r**2 / c%j_o * sin(c%theta_c)**2
        call check(error, printed < 0.0_dp, 'unfloored Res < 0')
        if (allocated(error)) return
        call check(error, c%e, 0.0_dp, atol=0.0_dp, message='Res floored at 0')
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg)
        call check(error, blk%e, 0.0_dp, atol=0.0_dp, message='block e = 0')
        if (allocated(error)) return
        ! h/r = 3/4 is the edge: Res = 0 there and positive above
        call make_cylinder(error, 1.0_dp, 0.8_dp, 1.0_dp, 9.81_dp, c)
        if (allocated(error)) return
        call check(error, c%e, 1.0_dp - 24.0_dp / (15.0_dp + 16.0_dp * 0.64_dp), &
                   rtol=1.0e-14_dp, message='Res > 0 above h/r = 3/4')
    end subroutine test_corrections

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: c, bad, out
        type(rocking_block_t) :: blk
        real(dp) :: nan, f, mo, pga(1)
        integer :: stat, cls(2, 2), cls1(1, 1), d(2, 2)
        logical :: st
        character(len=300) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        call make_cylinder(error, 0.5_dp, 1.5_dp, 10.0_dp, g0, c)
        if (allocated(error)) return
        msg = ''
        call cylinder_props(-1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg)
        call expect_bad(error, stat, msg, 'r = -1')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, nan, 1.0_dp, g0, out, stat, msg)
        call expect_bad(error, stat, msg, 'h = NaN')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 0.0_dp, g0, out, stat, msg)
        call expect_bad(error, stat, msg, 'mass = 0')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, ieee_value(1.0_dp, ieee_positive_inf), &
                            out, stat, msg)
        call expect_bad(error, stat, msg, 'g = ')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, r_inner=1.0_dp)
        call expect_bad(error, stat, msg, 'r_inner = 1')
        if (allocated(error)) return
        call check(error, index(msg, '[0, r)') > 0, 'r_inner message gives the range')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, r_inner=-0.1_dp)
        call expect_bad(error, stat, msg, 'r_inner')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, j_o=1.9_dp)
        call expect_bad(error, stat, msg, 'j_o = 1.9')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, j_o=nan)
        call expect_bad(error, stat, msg, 'j_o = NaN')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, j_o=3.0_dp, &
                            j_axis=-1.0_dp)
        call expect_bad(error, stat, msg, 'j_axis = -1')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, j_axis=1.0_dp)
        call expect_bad(error, stat, msg, 'j_axis = 1')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, j_o=3.0_dp, &
                            j_axis=nan)
        call check(error, stat, SEISPULSE_SUCCESS, 'j_axis NaN = unknown')
        if (allocated(error)) return
        call cylinder_props(1.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg, r_inner=0.5_dp, &
                            j_o=3.0_dp)
        call expect_bad(error, stat, msg, 'not both')
        if (allocated(error)) return
        call block_props(0.0_dp, 1.0_dp, 1.0_dp, g0, out, stat, msg)
        call expect_bad(error, stat, msg, 'b = 0')
        if (allocated(error)) return
        call block_props(1.0_dp, 1.0_dp, 1.0e40_dp, g0, out, stat, msg)
        call expect_bad(error, stat, msg, 'mass = ')
        if (allocated(error)) return
        call rigid_pushover(c, 2.0_dp, f, mo, st, stat, msg)
        call expect_bad(error, stat, msg, 'theta = 2')
        if (allocated(error)) return
        call check(error, ieee_is_nan(f) .and. ieee_is_nan(mo) .and. .not. st, 'NaN outputs')
        if (allocated(error)) return
        call check(error, ieee_is_nan(normalized_pushover(0.0_dp, 0.5_dp)), &
                   'normalized_pushover: theta_c = 0 is NaN')
        if (allocated(error)) return
        call body_rocking_block(c, blk, stat, msg, e=1.5_dp)
        call expect_bad(error, stat, msg, 'e = 1.5')
        if (allocated(error)) return
        bad = c
        bad%shape = 7
        call body_rocking_block(bad, blk, stat, msg)
        call expect_bad(error, stat, msg, 'body%shape = 7')
        if (allocated(error)) return
        bad = c
        bad%p = -1.0_dp
        call rigid_pushover(bad, 0.1_dp, f, mo, st, stat, msg)
        call expect_bad(error, stat, msg, 'body%p')
        if (allocated(error)) return
        call equivalent_cylinder(c, out, stat, msg, theta_c=2.0_dp)
        call expect_bad(error, stat, msg, 'theta_c = 2')
        if (allocated(error)) return
        call equivalent_cylinder(bad, out, stat, msg)
        call expect_bad(error, stat, msg, 'block%p')
        if (allocated(error)) return
        call equivalent_block(c, out, stat, msg, alpha=0.0_dp)
        call expect_bad(error, stat, msg, 'alpha = 0')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_SINE_CYCLE, [1.0_dp, 1.0_dp], [1.0_dp, 1.0_dp], 3, &
                                  cls, stat, msg)
        call expect_bad(error, stat, msg, 'axes = 3')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_SINE_CYCLE, [1.0_dp, 0.0_dp], [1.0_dp, 1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call expect_bad(error, stat, msg, 'x(2) = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'Hz') > 0, 'x message gives the unit')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_SINE_CYCLE, [1.0_dp, 1.0_dp], [-1.0_dp, 1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call expect_bad(error, stat, msg, 'y(1) = -1')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_SINE_CYCLE, [1.0e308_dp, 1.0_dp], [1.0_dp, 1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call expect_bad(error, stat, msg, 'x(1) = ')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_MP, [1.0_dp, 1.0_dp], [1.0_dp, 1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call expect_bad(error, stat, msg, 'kind = ')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_HALF_SINE, [1.0_dp], [1.0_dp, 1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call expect_bad(error, stat, msg, 'classes')
        if (allocated(error)) return
        call body_overturning_map(c, PULSE_HALF_SINE, [1.0_dp], [1.0_dp], &
                                  MAP_AXES_DIMENSIONAL, cls1, stat, msg, e=-0.1_dp)
        call expect_bad(error, stat, msg, 'e = -0.1')
        if (allocated(error)) return
        call map_difference(cls, cls1, d, stat, msg)
        call expect_bad(error, stat, msg, 'classes_b')
        if (allocated(error)) return
        cls = 0
        cls(1, 2) = 4
        call map_difference(cls, cls, d, stat, msg)
        call expect_bad(error, stat, msg, 'classes_a(1, 2) = 4')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_SINE_CYCLE, [1.0_dp], pga, stat, msg, n_scan=1)
        call expect_bad(error, stat, msg, 'n_scan = 1')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_SINE_CYCLE, [1.0_dp], pga, stat, msg, &
                                   pga_max_g=0.1_dp)
        call expect_bad(error, stat, msg, 'pga_max_g = 0.1')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_SINE_CYCLE, [-1.0_dp], pga, stat, msg)
        call expect_bad(error, stat, msg, 'freq_hz(1) = -1')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_SINE_CYCLE, [1.0_dp, 2.0_dp], pga, stat, msg)
        call expect_bad(error, stat, msg, 'pga_g')
        if (allocated(error)) return
        call overturning_threshold(c, PULSE_MP, [1.0_dp], pga, stat, msg)
        call expect_bad(error, stat, msg, 'kind = ')
    end subroutine test_bad_input

end module test_cylinder
