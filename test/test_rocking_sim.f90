!> Rocking integrator: block properties, free rocking (energy, Housner's period, the
!> exact nonlinear period by quadrature), closed forms of doc/rocking.md for the linearized
!> model (rectangle 2.12/2.13/2.25/2.29/2.33, triangle 2.14, exponential 2.4/2.10 and the
!> O3 critical time, Housner's wall 2.21), restitution and rest, nonlinear vs linearized
!> as alpha -> 0, the two overturning modes of Zhang & Makris (2001), records against
!> pulses, maps against single runs and the wall, grid output and bad input.
module test_rocking_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_pulses, only: pulse_t, pulse_at, exponential_pulse, half_sine_pulse, &
                                sine_cycle_pulse, cosine_cycle_pulse, rectangular_pulse, &
                                triangular_pulse, ricker_pulse, mp_pulse, PULSE_SINE_CYCLE, &
                                PULSE_COSINE_CYCLE, PULSE_RECTANGULAR, PULSE_HALF_SINE, &
                                PULSE_MP
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, rectangular_block, &
                                     symmetric_block, rocking_block_validate, rock_pulse, &
                                     rock_record, overturning_map, ROCK_RUN_REST, ROCK_RUN_NO_UPLIFT, &
                                     ROCK_RUN_OVERTURN_NO_IMPACT, ROCK_RUN_OVERTURN_ONE_IMPACT, &
                                     ROCK_RUN_OVERTURN_MANY, ROCK_RUN_TIME_LIMIT
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_rocking_sim

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp

contains

    subroutine collect_rocking_sim(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('block properties: 3-4-5 rectangle, symmetric bodies', &
                              test_blocks), &
                 new_unittest('free rocking e = 1: energy, exact and Housner periods', &
                              test_free_rocking), &
                 new_unittest('linearized rectangle: 2.12, 2.13, 2.25, 2.29, 2.33', &
                              test_rectangle_closed_form), &
                 new_unittest('linearized triangle (2.14) and exponential (2.4, 2.10, O3)', &
                              test_exponential_closed_form), &
                 new_unittest('Housner wall 2.21; nonlinear/linearized -> tan(a)/a', &
                              test_wall_and_small_alpha), &
                 new_unittest('restitution: impact sequence, e^2 per impact, rest time', &
                              test_restitution), &
                 new_unittest('one-sine, one-cosine: two modes and the safe region (Z&M)', &
                              test_two_modes), &
                 new_unittest('nonlinear impacts under cycle pulses vs independent ODE', &
                              test_independent), &
                 new_unittest('sampled rectangle and triangle equal the pulses', &
                              test_records), &
                 new_unittest('Ricker and M&P pulses against records (order dt^2)', &
                              test_smooth_pulses), &
                 new_unittest('record units: samples in g times the g argument', &
                              test_record_units), &
                 new_unittest('maps: single runs, the linearized wall, monotone cells', &
                              test_maps), &
                 new_unittest('grid output, outcomes, initial states', test_grid_outcomes), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input), &
                 new_unittest('vertical: kv = 0 and a zero accel_v are bit for bit', &
                              test_vertical_identity), &
                 new_unittest('vertical: constant a_v = block with g + a_v, p^2 (1 + a_v/g)', &
                              test_vertical_constant), &
                 new_unittest('vertical: uplift thresholds (R.11), (R.10) on a record', &
                              test_vertical_uplift), &
                 new_unittest('vertical: a_v < -g refused naming kv / accel_v', &
                              test_vertical_bad)]
    end subroutine collect_rocking_sim

    ! ---------------------------------------------------------------- helpers

    function make_block(alpha, p, e, linearized, g) result(blk)
        real(dp), intent(in) :: alpha, p, e
        logical, intent(in) :: linearized
        real(dp), intent(in), optional :: g
        type(rocking_block_t) :: blk
        blk%alpha = alpha
        blk%p = p
        blk%e = e
        blk%linearized = linearized
        if (present(g)) blk%g = g
    end function make_block

    !> Run a pulse; fail unless the status is success.
    subroutine run_ok(error, blk, pl, run, label, t_grid, th, om, t_max, theta0)
        type(test_error), allocatable, intent(inout) :: error
        type(rocking_block_t), intent(in) :: blk
        type(pulse_t), intent(in) :: pl
        type(rocking_run_t), intent(out) :: run
        character(len=*), intent(in) :: label
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: th(:), om(:)
        real(dp), intent(in), optional :: t_max, theta0
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call rock_pulse(blk, pl, run, stat, msg, t_grid, th, om, t_max=t_max, theta0=theta0)
        call check(error, stat, SEISPULSE_SUCCESS, label//': status ('//trim(msg)//')')
    end subroutine run_ok

    logical function overturned(run)
        type(rocking_run_t), intent(in) :: run
        overturned = run%outcome == ROCK_RUN_OVERTURN_NO_IMPACT .or. &
                     run%outcome == ROCK_RUN_OVERTURN_ONE_IMPACT .or. run%outcome == ROCK_RUN_OVERTURN_MANY
    end function overturned

    !> Gauss-Legendre nodes and weights on (-1, 1) (Newton on P_n).
    subroutine gauss_legendre(n, x, w)
        integer, intent(in) :: n
        real(dp), intent(out) :: x(n), w(n)
        integer :: i, j, it
        real(dp) :: z, z1, p1, p2, p3, pp
        do i = 1, n
            z = cos(pi * (real(i, dp) - 0.25_dp) / (real(n, dp) + 0.5_dp))
            pp = 1.0_dp
            do it = 1, 100
                p1 = 1.0_dp
                p2 = 0.0_dp
                do j = 1, n
                    p3 = p2
                    p2 = p1
                    p1 = (real(2 * j - 1, dp) * z * p2 - real(j - 1, dp) * p3) / real(j, dp)
                end do
                pp = real(n, dp) * (z * p1 - p2) / (z * z - 1.0_dp)
                z1 = z
                z = z1 - p1 / pp
                if (abs(z - z1) < 1.0e-15_dp) exit
            end do
            x(i) = -z
            w(i) = 2.0_dp / ((1.0_dp - z * z) * pp * pp)
        end do
    end subroutine gauss_legendre

    !> Exact time from rest at theta_m to theta = 0 of the NONLINEAR free block
    !> (energy: theta'^2 = 2 p^2 [cos(alpha - theta_m) - cos(alpha - theta)]), by
    !> Gauss-Legendre after theta = theta_m (1 - v^2), which removes the endpoint
    !> singularity: dt = 2 theta_m dv / sqrt(2 p^2 D/v^2), D/v^2 smooth.
    function quarter_period(alpha, p, thm) result(q)
        real(dp), intent(in) :: alpha, p, thm
        real(dp) :: q
        integer, parameter :: n = 64
        real(dp) :: x(n), w(n), v, dv2
        integer :: k
        call gauss_legendre(n, x, w)
        q = 0.0_dp
        do k = 1, n
            v = 0.5_dp * (x(k) + 1.0_dp)
            dv2 = 2.0_dp * sin(alpha - thm + 0.5_dp * thm * v * v) &
                  * sin(0.5_dp * thm * v * v) / (v * v)
            q = q + 0.5_dp * w(k) * 2.0_dp * thm / sqrt(2.0_dp * p * p * dv2)
        end do
    end function quarter_period

    !> Run-length compressed class sequence.
    subroutine compress(c, out, n)
        integer, intent(in) :: c(:)
        integer, intent(out) :: out(:)
        integer, intent(out) :: n
        integer :: i
        n = 0
        do i = 1, size(c)
            if (n > 0) then
                if (out(n) == c(i)) cycle
            end if
            if (n == size(out)) then
                n = n + 1
                return
            end if
            n = n + 1
            out(n) = c(i)
        end do
    end subroutine compress

    ! ---------------------------------------------------------------- tests

    subroutine test_blocks(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk, blk2
        integer :: stat
        real(dp) :: io_over_m
        ! b = 0.3, h = 0.4: R = 0.5, sin(alpha) = 0.6; I_o = m (0.6^2 + 0.8^2)/12 + m R^2
        call rectangular_block(0.3_dp, 0.4_dp, g0, blk, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'rectangular_block')
        if (allocated(error)) return
        io_over_m = (0.36_dp + 0.64_dp) / 12.0_dp + 0.25_dp
        call check(error, blk%alpha, atan(0.75_dp), rtol=1.0e-15_dp, message='alpha')
        if (allocated(error)) return
        call check(error, blk%p, sqrt(g0 * 0.5_dp / io_over_m), rtol=1.0e-15_dp, message='p')
        if (allocated(error)) return
        ! Housner: e = 1 - 1.5 sin^2(alpha) = 1 - 1.5 * 0.36
        call check(error, blk%e, 0.46_dp, rtol=1.0e-14_dp, message='e')
        if (allocated(error)) return
        call check(error, blk%g, g0, message='g')
        if (allocated(error)) return
        ! the same body as a symmetric block with I_o/(m R^2) = (1/3)/0.25 = 4/3
        call symmetric_block(0.5_dp, atan(0.75_dp), 4.0_dp / 3.0_dp, g0, blk2, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'symmetric_block')
        if (allocated(error)) return
        call check(error, blk2%p, blk%p, rtol=1.0e-15_dp, message='symmetric p')
        if (allocated(error)) return
        call check(error, blk2%e, 0.46_dp, rtol=1.0e-14_dp, message='symmetric e')
        if (allocated(error)) return
        ! I_o = 2 m R^2: p = sqrt(g/(2 R)), e = 1 - sin^2(alpha) = 0.64
        call symmetric_block(0.5_dp, atan(0.75_dp), 2.0_dp, g0, blk2, stat)
        call check(error, blk2%p, sqrt(g0), rtol=1.0e-15_dp, message='I_o = 2 m R^2: p')
        if (allocated(error)) return
        call check(error, blk2%e, 0.64_dp, rtol=1.0e-14_dp, message='I_o = 2 m R^2: e')
        if (allocated(error)) return
        ! squat body: 1 - 2 sin^2(1) = cos(2) < 0 -> 0
        call symmetric_block(1.0_dp, 1.0_dp, 1.0_dp, g0, blk2, stat)
        call check(error, blk2%e, 0.0_dp, message='negative Housner e is clipped')
        if (allocated(error)) return
        call rocking_block_validate(blk, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'validate')
    end subroutine test_blocks

    !> e = 1, released from theta0 at rest (a_g = 0): the energy is constant and the
    !> impacts fall at T/4 + (k - 1) T/2; T from quadrature (nonlinear) and from Housner's
    !> T = (4/p) acosh(1/(1 - theta0/alpha)) (linearized).
    subroutine test_free_rocking(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: none
        integer, parameter :: ng = 1501
        real(dp) :: tg(ng), th(ng), om(ng), alpha, p, th0, e0, en, de, tq, tt
        integer :: i, k, n
        alpha = 0.3_dp
        p = 1.7_dp
        th0 = 0.6_dp * alpha
        none = rectangular_pulse(0.0_dp, 1.0_dp)
        do i = 1, ng
            tg(i) = 40.0_dp * real(i - 1, dp) / real(ng - 1, dp)
        end do
        blk = make_block(alpha, p, 1.0_dp, .false.)
        call run_ok(error, blk, none, run, 'nonlinear', tg, th, om, t_max=40.0_dp, theta0=th0)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_TIME_LIMIT, 'perpetual rocking ends at t_max')
        if (allocated(error)) return
        e0 = p * p * cos(alpha - th0)
        de = 0.0_dp
        do i = 1, ng
            en = 0.5_dp * om(i)**2 + p * p * cos(alpha - abs(th(i)))
            de = max(de, abs(en - e0))
        end do
        call check(error, de, 0.0_dp, atol=1.0e-8_dp * p * p, message='energy E conserved')
        if (allocated(error)) return
        call check(error, run%theta_max, th0, rtol=1.0e-10_dp, message='theta_max')
        if (allocated(error)) return
        call check(error, run%theta_min, -th0, rtol=1.0e-10_dp, message='theta_min')
        if (allocated(error)) return
        tq = quarter_period(alpha, p, th0)
        n = run%n_impacts
        call check(error, n, int((40.0_dp / tq + 1.0_dp) / 2.0_dp), 'number of impacts')
        if (allocated(error)) return
        do k = 1, n
            call check(error, run%t_impacts(k), real(2 * k - 1, dp) * tq, rtol=1.0e-10_dp, &
                       message='nonlinear impact times (exact period by quadrature)')
            if (allocated(error)) return
        end do
        ! the nonlinear period is longer than Housner's linearized one
        tt = 4.0_dp / p * acosh(1.0_dp / (1.0_dp - th0 / alpha))
        call check(error, 4.0_dp * tq > tt, 'nonlinear period > linearized period')
        if (allocated(error)) return
        blk%linearized = .true.
        call run_ok(error, blk, none, run, 'linearized', t_max=40.0_dp, theta0=th0)
        if (allocated(error)) return
        do k = 1, run%n_impacts
            call check(error, run%t_impacts(k), tt / 4.0_dp + real(k - 1, dp) * tt / 2.0_dp, &
                       rtol=1.0e-10_dp, message='Housner period T = (4/p) acosh(1/(1-t0/a))')
            if (allocated(error)) return
        end do
        call check(error, run%n_impacts >= 20, 'linearized: many periods checked')
    end subroutine test_free_rocking

    !> Rectangular pulse of duration t_d, eta = alpha g/A, f = p t_d (doc/rocking.md 2, 4, 6).
    subroutine test_rectangle_closed_form(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: pl
        integer, parameter :: ng = 400
        real(dp) :: tg(ng), th(ng), om(ng), alpha, p, f, eta, td, tau, psi, dpsi, tau_m
        real(dp) :: thm, tau_i, z, tmg(1), thg(1), omg(1)
        integer :: i, j
        real(dp), parameter :: fs(2) = [1.0_dp, 0.4_dp], etas(2) = [0.7_dp, 0.5_dp]
        alpha = 0.1_dp
        p = 2.0_dp
        do j = 1, 2
            f = fs(j)
            eta = etas(j)
            td = f / p
            blk = make_block(alpha, p, 0.94_dp, .true.)
            pl = rectangular_pulse(g0 * alpha / eta, td)
            ! Eq. 2.33 (equivalent form of section 7): tau_i = ln(z)/f
            z = (eta + 2.0_dp * sqrt(1.0_dp - eta) * sinh(0.5_dp * f)) &
                / (exp(-f) - (1.0_dp - eta))
            tau_i = log(z) / f
            do i = 1, ng
                tg(i) = tau_i * td * real(i - 1, dp) / real(ng, dp)
            end do
            call run_ok(error, blk, pl, run, 'rectangle', tg, th, om)
            if (allocated(error)) return
            call check(error, run%outcome, ROCK_RUN_REST, 'rectangle in region S comes to rest')
            if (allocated(error)) return
            call check(error, run%t_uplift, 0.0_dp, message='uplift at once')
            if (allocated(error)) return
            call check(error, run%t_impacts(1), tau_i * td, atol=1.0e-10_dp, &
                       message='first impact, Eq. 2.33')
            if (allocated(error)) return
            do i = 1, ng
                tau = tg(i) / td
                ! Eqs. 2.12, 2.13
                psi = (1.0_dp / eta - 1.0_dp) * (cosh(f * tau) - 1.0_dp)
                dpsi = (1.0_dp / eta - 1.0_dp) * sinh(f * tau)
                if (tau > 1.0_dp) then
                    psi = psi - (cosh(f * (tau - 1.0_dp)) - 1.0_dp) / eta
                    dpsi = dpsi - sinh(f * (tau - 1.0_dp)) / eta
                end if
                call check(error, th(i) / alpha, psi, atol=1.0e-9_dp, message='Eq. 2.12')
                if (allocated(error)) return
                call check(error, om(i) / (alpha * p), dpsi, atol=1.0e-9_dp, message='Eq. 2.13')
                if (allocated(error)) return
            end do
            ! Eq. 2.25 (time of the maximum) and 2.29 (the maximum)
            tau_m = log((1.0_dp - eta - exp(f)) / (1.0_dp - eta - exp(-f))) / (2.0_dp * f)
            thm = alpha / eta * (eta + (1.0_dp - eta) * cosh(f * tau_m) &
                                 - cosh(f * (tau_m - 1.0_dp)))
            call check(error, run%theta_max, thm, rtol=1.0e-9_dp, message='Eq. 2.29')
            if (allocated(error)) return
            call check(error, run%t_theta_max, tau_m * td, rtol=1.0e-9_dp, &
                       message='time of theta_max, Eq. 2.25')
            if (allocated(error)) return
            ! the mirror image: the same extreme and time on the other side
            call run_ok(error, blk, rectangular_pulse(-g0 * alpha / eta, td), run, &
                        'rectangle, negative')
            if (allocated(error)) return
            call check(error, run%theta_min, -thm, rtol=1.0e-9_dp, message='Eq. 2.29, mirrored')
            if (allocated(error)) return
            call check(error, run%t_theta_min, tau_m * td, rtol=1.0e-9_dp, &
                       message='time of theta_min, Eq. 2.25 mirrored')
            if (allocated(error)) return
            ! theta > 0 only after the first impact (e = 0.94: it rocks back)
            call check(error, run%t_theta_max > tau_i * td, &
                       'time of theta_max after the first impact, mirrored')
            if (allocated(error)) return
            tmg(1) = tau_m * td
            call run_ok(error, blk, pl, run, 'rectangle at tau_m', tmg, thg, omg)
            if (allocated(error)) return
            call check(error, omg(1), 0.0_dp, atol=1.0e-9_dp * alpha * p, &
                       message='theta'' = 0 at tau_m of Eq. 2.25')
            if (allocated(error)) return
            call check(error, thg(1), thm, rtol=1.0e-9_dp, message='theta(tau_m)')
            if (allocated(error)) return
        end do
    end subroutine test_rectangle_closed_form

    !> Triangle (Eq. 2.14) and the exponential pulse beta = pi in the stable phase-wise
    !> form of doc/rocking.md section 2 (Eqs. 2.4, 2.10), and the O3 critical time of its section 3.
    subroutine test_exponential_closed_form(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run, run2
        type(pulse_t) :: pl
        integer, parameter :: ng = 300
        real(dp) :: tg(ng), th(ng), om(ng), alpha, p, f, eta, td, tau, psi, beta, q, tup
        real(dp) :: c, den, x, psi1, dpsi1, aa, bb, tau_c
        integer :: i
        alpha = 0.05_dp
        p = 1.5_dp
        blk = make_block(alpha, p, 0.9_dp, .true.)
        ! ---- triangle: f = 3, eta = 0.8 (safe: eta_w = 0.617, Eq. 2.22); Eq. 2.14 for
        ! tau >= tau_up = eta/2
        f = 3.0_dp
        eta = 0.8_dp
        td = f / p
        pl = triangular_pulse(g0 * alpha / eta, td, 0.5_dp)
        do i = 1, ng
            tg(i) = td * (0.5_dp * eta + 1.5_dp * real(i - 1, dp) / real(ng, dp))
        end do
        call run_ok(error, blk, pl, run, 'triangle', tg, th, om)
        if (allocated(error)) return
        call check(error, run%t_uplift, 0.5_dp * eta * td, rtol=1.0e-14_dp, &
                   message='triangle uplift tau_up = eta/2')
        if (allocated(error)) return
        do i = 1, ng
            tau = tg(i) / td
            if (run%n_impacts > 0) then
                if (tg(i) >= run%t_impacts(1)) exit
            end if
            psi = 1.0_dp - (2.0_dp * tau - 2.0_dp / f * sinh(f * (tau - 0.5_dp * eta))) / eta
            if (tau > 0.5_dp) psi = psi - (2.0_dp - 4.0_dp * tau &
                                           + 4.0_dp / f * sinh(f * (tau - 0.5_dp))) / eta
            if (tau > 1.0_dp) psi = psi - (2.0_dp * (tau - 1.0_dp) &
                                           - 2.0_dp / f * sinh(f * (tau - 1.0_dp))) / eta
            call check(error, th(i) / alpha, psi, atol=1.0e-9_dp, message='Eq. 2.14')
            if (allocated(error)) return
        end do
        ! the exponential pulse with beta = 0 is the same triangle
        pl = exponential_pulse(g0 * alpha / eta, td, 0.0_dp, .false.)
        call run_ok(error, blk, pl, run2, 'exponential beta = 0')
        if (allocated(error)) return
        call check(error, run2%t_impacts(1), run%t_impacts(1), rtol=1.0e-11_dp, &
                   message='beta = 0 equals the triangle')
        if (allocated(error)) return

        ! ---- beta = pi, f = 1, eta = 0.3 (safe) on a grid; eta = 0.15 in O3
        beta = pi
        f = 1.0_dp
        td = f / p
        c = 1.0_dp - exp(beta)
        eta = 0.3_dp
        q = 1.0_dp - eta * c
        tup = log(q) / (2.0_dp * beta)
        pl = exponential_pulse(g0 * alpha / eta, td, beta, .false.)
        do i = 1, ng
            tg(i) = td * (tup + (1.0_dp - tup) * real(i - 1, dp) / real(ng - 1, dp))
        end do
        call run_ok(error, blk, pl, run, 'exponential', tg, th, om)
        if (allocated(error)) return
        call check(error, run%t_uplift, tup * td, rtol=1.0e-12_dp, message='Eq. 2.4')
        if (allocated(error)) return
        den = eta * c * (f * f - 4.0_dp * beta * beta)
        do i = 1, ng
            tau = tg(i) / td
            x = beta * (f + 2.0_dp * beta) * q * exp(f * (tau - tup)) &
                - beta * (f - 2.0_dp * beta) * q * exp(-f * (tau - tup)) - 4.0_dp * beta**2
            if (tau <= 0.5_dp) then
                x = x + f * f * (1.0_dp - exp(2.0_dp * beta * tau))
            else
                x = x + f * f * (1.0_dp - exp(2.0_dp * beta * (1.0_dp - tau))) &
                    - 4.0_dp * beta * f * exp(beta) * sinh(f * (tau - 0.5_dp))
            end if
            call check(error, th(i) / alpha, 1.0_dp - x / den, atol=1.0e-9_dp, &
                       message='Eq. 2.10 (phases 1-2)')
            if (allocated(error)) return
        end do
        ! O3: overturns after the pulse at tau_c = 1 + ln(-B/A)/(2f) (section 5.4)
        eta = 0.15_dp
        q = 1.0_dp - eta * c
        tup = log(q) / (2.0_dp * beta)
        den = eta * c * (f * f - 4.0_dp * beta * beta)
        x = beta * (f + 2.0_dp * beta) * q * exp(f * (1.0_dp - tup)) &
            - beta * (f - 2.0_dp * beta) * q * exp(-f * (1.0_dp - tup)) - 4.0_dp * beta**2 &
            + f * f * (1.0_dp - 1.0_dp) - 4.0_dp * beta * f * exp(beta) * sinh(0.5_dp * f)
        psi1 = 1.0_dp - x / den
        x = f * beta * (f + 2.0_dp * beta) * q * exp(f * (1.0_dp - tup)) &
            + f * beta * (f - 2.0_dp * beta) * q * exp(-f * (1.0_dp - tup)) &
            + 2.0_dp * beta * f * f - 4.0_dp * beta * f * f * exp(beta) * cosh(0.5_dp * f)
        dpsi1 = -x / den
        aa = 0.5_dp * (psi1 - 1.0_dp + dpsi1 / f)
        bb = 0.5_dp * (psi1 - 1.0_dp - dpsi1 / f)
        tau_c = 1.0_dp + log(-bb / aa) / (2.0_dp * f)
        ! doc/rocking.md section 3 oracle: beta = pi, f = 1, eta = 0.15 -> tau_c = 1.4103182142
        call check(error, tau_c, 1.4103182142_dp, atol=1.0e-9_dp, message='tau_c formula')
        if (allocated(error)) return
        pl = exponential_pulse(g0 * alpha / eta, td, beta, .false.)
        call run_ok(error, blk, pl, run, 'exponential O3')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_OVERTURN_NO_IMPACT, 'O3 overturns without impact')
        if (allocated(error)) return
        call check(error, run%t_overturn / td, tau_c, rtol=1.0e-9_dp, &
                   message='t_overturn = tau_c t_d')
        if (allocated(error)) return
        call check(error, run%t_end > run%t_overturn, 't_end (|theta| = pi/2) after tau_c')
    end subroutine test_exponential_closed_form

    !> Housner's minimum overturning amplitude of a rectangular pulse, linearized:
    !> eta_w = 1 - e^(-f) (Eq. 2.21), by bisection on the amplitude; and the nonlinear /
    !> linearized critical amplitudes as alpha -> 0 (ratio -> tan(alpha)/alpha: uplift at
    !> g tan(alpha) vs g alpha, the dynamics otherwise alike).
    subroutine test_wall_and_small_alpha(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a_lin, a_nl, f, alpha, r, rt
        real(dp), parameter :: alphas(3) = [0.1_dp, 0.05_dp, 0.02_dp]
        integer :: k
        f = 2.0_dp
        alpha = 0.1_dp
        call critical(error, alpha, .true., f, a_lin, 56)
        if (allocated(error)) return
        ! g = 1, p = 1: A_min = alpha/eta_w
        call check(error, a_lin, alpha / (1.0_dp - exp(-f)), rtol=1.0e-9_dp, &
                   message='Eq. 2.21 (Housner 1963)')
        if (allocated(error)) return
        do k = 1, 3
            alpha = alphas(k)
            call critical(error, alpha, .true., f, a_lin, 40)
            if (allocated(error)) return
            call critical(error, alpha, .false., f, a_nl, 40)
            if (allocated(error)) return
            r = a_nl / a_lin
            rt = tan(alpha) / alpha
            call check(error, r, rt, atol=0.1_dp * (rt - 1.0_dp), &
                       message='critical amplitude ratio near tan(alpha)/alpha')
            if (allocated(error)) return
            call check(error, r > 1.0_dp, 'the nonlinear block is more stable')
            if (allocated(error)) return
        end do
    contains
        subroutine critical(error, alpha, lin, f, a, nit)
            type(test_error), allocatable, intent(inout) :: error
            real(dp), intent(in) :: alpha, f
            logical, intent(in) :: lin
            real(dp), intent(out) :: a
            integer, intent(in) :: nit
            type(rocking_block_t) :: blk
            type(rocking_run_t) :: run
            real(dp) :: lo, hi
            integer :: it
            blk = make_block(alpha, 1.0_dp, 0.9_dp, lin, g=1.0_dp)
            lo = tan(alpha)
            hi = 10.0_dp * tan(alpha)
            do it = 1, nit
                a = 0.5_dp * (lo + hi)
                call run_ok(error, blk, rectangular_pulse(a, f), run, 'bisection')
                if (allocated(error)) return
                if (overturned(run)) then
                    hi = a
                else
                    lo = a
                end if
            end do
            a = 0.5_dp * (lo + hi)
        end subroutine critical
    end subroutine test_wall_and_small_alpha

    !> Free rocking with e < 1: the angular velocity at impact k is e^(k-1) times the first,
    !> so the kinetic energy (the energy above rest in the linearized model) falls by e^2
    !> per impact; impact times from the flight times (linearized: (2/p) atanh(w/(p alpha));
    !> nonlinear: quadrature); rest after the first impact whose next flight would rise
    !> less than 1e-10 alpha, at that impact plus tau/(1 - e).
    subroutine test_restitution(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: none
        real(dp) :: alpha, p, e, th0, w0, w, tk, thm, tau
        integer :: k, n_rest
        none = rectangular_pulse(0.0_dp, 1.0_dp)
        alpha = 0.2_dp
        p = 2.5_dp
        e = 0.7_dp
        th0 = 0.5_dp * alpha
        ! ---- linearized: E = theta'^2/2 + p^2 (alpha |theta| - theta^2/2)
        blk = make_block(alpha, p, e, .true.)
        call run_ok(error, blk, none, run, 'linearized decay', theta0=th0)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_REST, 'comes to rest')
        if (allocated(error)) return
        w0 = sqrt(2.0_dp * p * p * (alpha * th0 - 0.5_dp * th0**2))
        n_rest = 0
        w = w0
        do k = 1, 1000
            w = e * w
            ! next flight rises w^2/(2 p^2 alpha)
            if (0.5_dp * w * w / (p * p * alpha) <= 1.0e-10_dp * alpha) then
                n_rest = k
                exit
            end if
        end do
        call check(error, run%n_impacts, n_rest, 'impacts before rest')
        if (allocated(error)) return
        tk = 4.0_dp / p * acosh(1.0_dp / (1.0_dp - th0 / alpha)) / 4.0_dp
        w = w0
        do k = 1, run%n_impacts
            call check(error, run%t_impacts(k), tk, rtol=1.0e-10_dp, &
                       message='linearized impact times with restitution')
            if (allocated(error)) return
            w = e * w
            tk = tk + 2.0_dp / p * atanh(w / (p * alpha))
        end do
        tau = 2.0_dp * w / (p * p * alpha)
        call check(error, run%t_end, run%t_impacts(run%n_impacts) + tau / (1.0_dp - e), &
                   rtol=1.0e-12_dp, message='rest time')
        if (allocated(error)) return
        ! ---- nonlinear, Housner's e of a rectangle with this alpha
        e = 1.0_dp - 1.5_dp * sin(alpha)**2
        blk = make_block(alpha, p, e, .false.)
        call run_ok(error, blk, none, run, 'nonlinear decay', theta0=th0)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_REST, 'nonlinear: comes to rest')
        if (allocated(error)) return
        w = sqrt(2.0_dp * p * p * (cos(alpha - th0) - cos(alpha)))
        tk = quarter_period(alpha, p, th0)
        do k = 1, 12
            call check(error, run%t_impacts(k), tk, rtol=1.0e-10_dp, &
                       message='nonlinear impact times with restitution')
            if (allocated(error)) return
            w = e * w
            ! the flight after impact k rises to thm: cos(alpha - thm) = cos(alpha) + w^2/(2p^2)
            thm = alpha - acos(cos(alpha) + 0.5_dp * w * w / (p * p))
            tk = tk + 2.0_dp * quarter_period(alpha, p, thm)
        end do
        n_rest = 0
        w = sqrt(2.0_dp * p * p * (cos(alpha - th0) - cos(alpha)))
        do k = 1, 10000
            w = e * w
            if (0.5_dp * w * w / (p * p * sin(alpha)) <= 1.0e-10_dp * alpha) then
                n_rest = k
                exit
            end if
        end do
        call check(error, run%n_impacts, n_rest, 'nonlinear: impacts before rest')
    end subroutine test_restitution

    !> Zhang & Makris (2001, J. Eng. Mech. 127(5), abstract): under one-sine and one-cosine
    !> pulses a block overturns in two modes, with impacts and without, and the second
    !> leaves a safe region above the minimum overturning acceleration. No tabulated
    !> values of theirs were found to compare with; this checks that structure along
    !> the amplitude at fixed omega_p/p, and that each mode is what a single run gives.
    subroutine test_two_modes(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: na = 120
        real(dp) :: amp(na), alpha, e, fr(1)
        integer :: cls(na, 1), stat, i, seq(8), n, kinds(2), kk
        character(len=200) :: msg
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: pl
        real(dp), parameter :: frs(2) = [6.0_dp, 3.0_dp]
        alpha = 0.25_dp
        e = 1.0_dp - 1.5_dp * sin(alpha)**2
        kinds = [PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE]
        do i = 1, na
            amp(i) = 0.5_dp + 14.5_dp * real(i - 1, dp) / real(na - 1, dp)
        end do
        do kk = 1, 2
            fr(1) = frs(kk)
            msg = ''
            call overturning_map(alpha, e, kinds(kk), fr, amp, cls, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, 'map ('//trim(msg)//')')
            if (allocated(error)) return
            call compress(cls(:, 1), seq, n)
            call check(error, n, 4, 'safe, one impact, safe region, no impact: 4 bands')
            if (allocated(error)) return
            call check(error, all(seq(1:4) == [0, 2, 0, 1]), 'bands 0, 2, 0, 1')
            if (allocated(error)) return
            ! a cell of each overturning band, rerun in SI with p = 2 rad/s
            blk = make_block(alpha, 2.0_dp, e, .false.)
            do i = 1, na
                if (cls(i, 1) == 0) cycle
                if (kinds(kk) == PULSE_SINE_CYCLE) then
                    pl = sine_cycle_pulse(amp(i) * g0 * tan(alpha), two_pi_over(fr(1) * 2.0_dp))
                else
                    pl = cosine_cycle_pulse(amp(i) * g0 * tan(alpha), two_pi_over(fr(1) * 2.0_dp))
                end if
                call run_ok(error, blk, pl, run, 'single run')
                if (allocated(error)) return
                if (cls(i, 1) == 1) then
                    call check(error, run%outcome, ROCK_RUN_OVERTURN_NO_IMPACT, 'no-impact mode')
                else
                    call check(error, run%outcome, ROCK_RUN_OVERTURN_ONE_IMPACT, 'one-impact mode')
                end if
                if (allocated(error)) return
            end do
        end do
    end subroutine test_two_modes

    pure function two_pi_over(w) result(t)
        real(dp), intent(in) :: w
        real(dp) :: t
        t = 2.0_dp * pi / w
    end function two_pi_over

    !> Nonlinear Eqs. 2.5/2.6 with impacts during and after one-cycle pulses against an
    !> independent integration: SciPy 1.17 solve_ivp (DOP853, rtol 1e-13, atol 1e-16,
    !> terminal events at theta = 0 and |theta| = pi/2, restarted with theta' times e on
    !> the other side), computed once for this test; alpha = 0.2, p = 2 rad/s, e = 0.9,
    !> g = 9.80665, a_p in g tan(alpha), omega_p = 2 pi/T_p in p.
    subroutine test_independent(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: pl
        real(dp) :: a1, tp
        integer :: k
        ! one-cosine, a_p = 1.2, omega_p/p = 1.5: four impacts (three during the pulse),
        ! then |theta| = pi/2 at 4.153502457975117 s
        real(dp), parameter :: ref1(4) = [5.0163647034175929e-01_dp, 7.1243409904386357e-01_dp, &
                                          7.7659697505907876e-01_dp, 1.9561092586641509e+00_dp]
        ! one-cosine, a_p = 2.5, omega_p/p = 4: safe, the first six impacts
        real(dp), parameter :: ref2(6) = [4.0355481725615028e-01_dp, 1.8523842885949688e+00_dp, &
                                          3.0755698449211155e+00_dp, 4.0647214834426677e+00_dp, &
                                          4.8969604888202447e+00_dp, 5.6119591701871636e+00_dp]
        ! one-sine, a_p = 4, omega_p/p = 6: uplift at asin(1/4)/omega_p, safe
        real(dp), parameter :: ref3(6) = [6.4660057092075773e-01_dp, 2.4658831774769903e+00_dp, &
                                          3.7382823230090776e+00_dp, 4.7573445022930496e+00_dp, &
                                          5.6109069385097552e+00_dp, 6.3423354277797896e+00_dp]
        ! one-sine, a_p = 3, omega_p/p = 3: one impact after the pulse, pi/2 at 3.38423...
        blk = make_block(0.2_dp, 2.0_dp, 0.9_dp, .false.)
        a1 = g0 * tan(0.2_dp)
        tp = 2.0_dp * pi / 3.0_dp
        pl = cosine_cycle_pulse(1.2_dp * a1, tp)
        call run_ok(error, blk, pl, run, 'cosine 1.2')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_OVERTURN_MANY, 'overturns after several impacts')
        if (allocated(error)) return
        call check(error, run%n_impacts, 4, 'impacts before overturning')
        if (allocated(error)) return
        do k = 1, 4
            call check(error, run%t_impacts(k), ref1(k), rtol=1.0e-9_dp, message='impact times')
            if (allocated(error)) return
        end do
        call check(error, run%t_end, 4.153502457975117_dp, rtol=1.0e-9_dp, message='pi/2 reached')
        if (allocated(error)) return
        tp = 2.0_dp * pi / 8.0_dp
        pl = cosine_cycle_pulse(2.5_dp * a1, tp)
        call run_ok(error, blk, pl, run, 'cosine 2.5')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_REST, 'safe')
        if (allocated(error)) return
        do k = 1, 6
            call check(error, run%t_impacts(k), ref2(k), rtol=1.0e-9_dp, message='impact times')
            if (allocated(error)) return
        end do
        tp = 2.0_dp * pi / 12.0_dp
        pl = sine_cycle_pulse(4.0_dp * a1, tp)
        call run_ok(error, blk, pl, run, 'sine 4')
        if (allocated(error)) return
        call check(error, run%t_uplift, 0.021056687928506554_dp, rtol=1.0e-13_dp, &
                   message='uplift time')
        if (allocated(error)) return
        do k = 1, 6
            call check(error, run%t_impacts(k), ref3(k), rtol=1.0e-9_dp, message='impact times')
            if (allocated(error)) return
        end do
        tp = 2.0_dp * pi / 6.0_dp
        pl = sine_cycle_pulse(3.0_dp * a1, tp)
        call run_ok(error, blk, pl, run, 'sine 3')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_OVERTURN_ONE_IMPACT, 'overturns after one impact')
        if (allocated(error)) return
        call check(error, run%t_impacts(1), 1.339201545722725_dp, rtol=1.0e-9_dp, &
                   message='impact time')
        if (allocated(error)) return
        call check(error, run%t_end, 3.3842335158944543_dp, rtol=1.0e-9_dp, &
                   message='pi/2 reached')
        if (allocated(error)) return
        ! e = 0: the first impact ends the rocking there
        blk%e = 0.0_dp
        call run_ok(error, blk, rectangular_pulse(1.5_dp * a1, 0.3_dp), run, 'e = 0')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_REST, 'e = 0: rest')
        if (allocated(error)) return
        call check(error, run%n_impacts, 1, 'e = 0: one impact')
        if (allocated(error)) return
        call check(error, run%t_end, run%t_impacts(1), message='e = 0: rest at the impact')
    end subroutine test_independent

    !> A record that samples a piecewise-linear pulse exactly (a_g = 0 after the last
    !> sample) gives the pulse's response.
    subroutine test_records(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: rp, rr
        type(pulse_t) :: pl
        real(dp), allocatable :: acc(:)
        real(dp) :: td, amp, dt
        integer :: stat, i, k, m, j
        character(len=200) :: msg
        logical :: lin
        do j = 1, 2
            lin = j == 2
            blk = make_block(0.15_dp, 2.2_dp, 0.9_dp, lin)
            td = 0.8_dp
            amp = 1.6_dp * g0 * tan(0.15_dp)
            ! rectangle: n samples of amp on [0, td]
            pl = rectangular_pulse(amp, td)
            call run_ok(error, blk, pl, rp, 'rectangle pulse')
            if (allocated(error)) return
            m = 16
            allocate(acc(m + 1))
            acc = amp / g0
            dt = td / real(m, dp)
            msg = ''
            call rock_record(blk, acc, dt, g0, rr, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, 'record ('//trim(msg)//')')
            if (allocated(error)) return
            call same_run(error, rr, rp, 'sampled rectangle')
            if (allocated(error)) return
            deallocate(acc)
            ! symmetric triangle sampled at its peak: exact
            pl = triangular_pulse(2.5_dp * amp, td, 0.5_dp)
            call run_ok(error, blk, pl, rp, 'triangle pulse')
            if (allocated(error)) return
            m = 20
            allocate(acc(m + 1))
            dt = td / real(m, dp)
            do i = 1, m + 1
                k = i - 1
                acc(i) = 2.5_dp * amp &
                         * (1.0_dp - abs(real(k, dp) * dt - 0.5_dp * td) / (0.5_dp * td))
            end do
            ! in m/s^2: a record in units of g = 1 m/s^2
            call rock_record(blk, acc, dt, 1.0_dp, rr, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, 'record ('//trim(msg)//')')
            if (allocated(error)) return
            call same_run(error, rr, rp, 'sampled triangle')
            if (allocated(error)) return
            deallocate(acc)
        end do
    end subroutine test_records

    !> rock_record takes samples in g: with g = 8 (exact products) a record in g equals
    !> the same record in m/s^2 given with g = 1, bit for bit; the g argument counts (a
    !> quarter of it gives another run) and is not the block's g.
    subroutine test_record_units(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: r8, r1, rq
        real(dp) :: acc(41), dt
        integer :: i, stat
        blk = make_block(0.15_dp, 2.2_dp, 0.9_dp, .false.)
        dt = 0.02_dp
        do i = 1, size(acc)
            acc(i) = 0.375_dp * sin(real(i - 1, dp) * 0.15_dp)   ! peak ~ 0.37 g > tan(0.15)
        end do
        call rock_record(blk, acc, dt, 8.0_dp, r8, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'record in g')
        if (allocated(error)) return
        call rock_record(blk, 8.0_dp * acc, dt, 1.0_dp, r1, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'record in m/s^2')
        if (allocated(error)) return
        call check(error, r8%n_impacts >= 1, 'the record rocks the block')
        if (allocated(error)) return
        ! rtol = 0: equal to the last bit
        call check(error, r8%outcome, r1%outcome, 'same outcome')
        if (allocated(error)) return
        call check(error, r8%n_impacts, r1%n_impacts, 'same impacts')
        if (allocated(error)) return
        call check(error, r8%n_steps, r1%n_steps, 'same steps')
        if (allocated(error)) return
        call check(error, [r8%t_uplift, r8%theta_max, r8%theta_min, r8%t_end, r8%t_impacts], &
                   [r1%t_uplift, r1%theta_max, r1%theta_min, r1%t_end, r1%t_impacts], &
                   rtol=0.0_dp, message='g * accel: the same run bit for bit')
        if (allocated(error)) return
        ! 2 m/s^2 peak 0.75 m/s^2 < g0 tan(0.15) = 1.48 m/s^2: no uplift
        call rock_record(blk, acc, dt, 2.0_dp, rq, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'record, g = 2')
        if (allocated(error)) return
        call check(error, rq%outcome, ROCK_RUN_NO_UPLIFT, 'g = 2: no uplift')
    end subroutine test_record_units

    subroutine same_run(error, a, b, label)
        type(test_error), allocatable, intent(inout) :: error
        type(rocking_run_t), intent(in) :: a, b
        character(len=*), intent(in) :: label
        integer :: k
        call check(error, a%outcome, b%outcome, label//': outcome')
        if (allocated(error)) return
        call check(error, a%n_impacts, b%n_impacts, label//': impacts')
        if (allocated(error)) return
        do k = 1, a%n_impacts
            call check(error, a%t_impacts(k), b%t_impacts(k), rtol=1.0e-10_dp, &
                       message=label//': impact time')
            if (allocated(error)) return
        end do
        call check(error, a%t_uplift, b%t_uplift, rtol=1.0e-12_dp, atol=1.0e-14_dp, &
                   message=label//': uplift')
        if (allocated(error)) return
        call check(error, a%theta_max, b%theta_max, rtol=1.0e-10_dp, message=label//': theta_max')
        if (allocated(error)) return
        call check(error, a%theta_min, b%theta_min, rtol=1.0e-10_dp, atol=1.0e-14_dp, &
                   message=label//': theta_min')
        if (allocated(error)) return
        call check(error, a%t_end, b%t_end, rtol=1.0e-9_dp, message=label//': t_end')
    end subroutine same_run

    !> Smooth pulses (Ricker, M&P, half-sine): the pulse run against records sampled at
    !> dt and dt/2 (linear interpolation, error O(dt^2)): the error of the first impact
    !> time falls about fourfold.
    subroutine test_smooth_pulses(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: rp, r1, r2
        type(pulse_t) :: pl
        real(dp) :: e1, e2, tend, amp
        integer :: kp
        blk = make_block(0.12_dp, 2.0_dp, 0.92_dp, .false.)
        amp = 2.2_dp * g0 * tan(0.12_dp)
        do kp = 1, 3
            select case (kp)
            case (1)
                pl = ricker_pulse(amp, 0.8_dp, 1.5_dp)
                tend = 1.5_dp + 10.0_dp / (pi * 0.8_dp)
            case (2)
                ! M&P: velocity amplitude 0.25 m/s, f_p = 1 Hz, peak a ~ 2 pi f_p A ~ 1.6 m/s^2
                pl = mp_pulse(0.25_dp, 1.0_dp, 2.0_dp, 30.0_dp, 1.2_dp)
                tend = 1.2_dp + 1.0_dp
            case default
                pl = half_sine_pulse(0.6_dp * amp, 0.5_dp)
                tend = 0.5_dp
            end select
            call run_ok(error, blk, pl, rp, 'pulse')
            if (allocated(error)) return
            call check(error, rp%n_impacts >= 1, 'the test pulse makes the block impact')
            if (allocated(error)) return
            call sampled(pl, tend, 400, r1)
            if (allocated(error)) return
            call sampled(pl, tend, 800, r2)
            if (allocated(error)) return
            e1 = abs(r1%t_impacts(1) - rp%t_impacts(1))
            e2 = abs(r2%t_impacts(1) - rp%t_impacts(1))
            call check(error, e1 < 1.0e-3_dp .and. e2 > 0.0_dp, 'records close to the pulse')
            if (allocated(error)) return
            call check(error, e1 / e2, 4.0_dp, rtol=0.25_dp, message='second order in dt')
            if (allocated(error)) return
        end do
    contains
        subroutine sampled(pl, tend, n, run)
            type(pulse_t), intent(in) :: pl
            real(dp), intent(in) :: tend
            integer, intent(in) :: n
            type(rocking_run_t), intent(out) :: run
            real(dp) :: acc(n + 1), v, d, dt
            integer :: i, stat
            dt = tend / real(n, dp)
            do i = 1, n + 1
                call pulse_at(pl, real(i - 1, dp) * dt, acc(i), v, d)
            end do
            call rock_record(blk, acc / g0, dt, g0, run, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'sampled record')
        end subroutine sampled
    end subroutine test_smooth_pulses

    !> Maps: cells equal single runs (p = 1, g = 1); the linearized rectangle map equals
    !> Eq. 2.21 (overturns without impact iff eta < 1 - e^(-f), eta = alpha/(r tan alpha),
    !> f = 2 pi/freq_ratio); at a low frequency ratio overturning is monotone in amplitude.
    subroutine test_maps(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: na = 7, nf = 5, nb = 40
        real(dp) :: amp(na), fr(nf), alpha, e, eta, etaw, ampb(nb), f1(1)
        integer :: cls(na, nf), clsb(nb, 1), stat, i, j, expect
        character(len=200) :: msg
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: pl
        logical :: seen
        alpha = 0.2_dp
        e = 0.85_dp
        amp = [0.8_dp, 1.5_dp, 2.5_dp, 4.0_dp, 6.0_dp, 9.0_dp, 13.0_dp]
        fr = [0.7_dp, 1.5_dp, 3.0_dp, 5.0_dp, 8.0_dp]
        msg = ''
        call overturning_map(alpha, e, PULSE_SINE_CYCLE, fr, amp, cls, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'map ('//trim(msg)//')')
        if (allocated(error)) return
        blk = make_block(alpha, 1.0_dp, e, .false., g=1.0_dp)
        do j = 1, nf
            do i = 1, na
                pl = sine_cycle_pulse(amp(i) * tan(alpha), 2.0_dp * pi / fr(j))
                call run_ok(error, blk, pl, run, 'single run')
                if (allocated(error)) return
                select case (run%outcome)
                case (ROCK_RUN_OVERTURN_NO_IMPACT)
                    expect = 1
                case (ROCK_RUN_OVERTURN_ONE_IMPACT)
                    expect = 2
                case (ROCK_RUN_OVERTURN_MANY)
                    expect = 3
                case default
                    expect = 0
                end select
                call check(error, cls(i, j), expect, 'map cell = single run')
                if (allocated(error)) return
            end do
        end do
        call check(error, any(cls == 1) .and. any(cls == 2) .and. any(cls == 0), &
                   'the map shows safe cells and both modes')
        if (allocated(error)) return
        ! linearized rectangle: the wall of Eq. 2.21
        call overturning_map(alpha, e, PULSE_RECTANGULAR, fr, amp, cls, stat, msg, &
                             linearized=.true.)
        call check(error, stat, SEISPULSE_SUCCESS, 'linearized map ('//trim(msg)//')')
        if (allocated(error)) return
        do j = 1, nf
            etaw = 1.0_dp - exp(-2.0_dp * pi / fr(j))
            do i = 1, na
                eta = alpha / (amp(i) * tan(alpha))
                expect = 0
                if (eta < etaw) expect = 1
                call check(error, cls(i, j), expect, 'linearized map = Eq. 2.21')
                if (allocated(error)) return
            end do
        end do
        ! low frequency ratio: once overturned, overturned at every larger amplitude
        do i = 1, nb
            ampb(i) = 0.5_dp + 4.0_dp * real(i - 1, dp) / real(nb - 1, dp)
        end do
        f1(1) = 0.3_dp
        do j = 1, 2
            if (j == 1) then
                call overturning_map(alpha, e, PULSE_HALF_SINE, f1, ampb, clsb, stat, msg)
            else
                call overturning_map(alpha, e, PULSE_RECTANGULAR, f1, ampb, clsb, stat, msg)
            end if
            call check(error, stat, SEISPULSE_SUCCESS, 'map ('//trim(msg)//')')
            if (allocated(error)) return
            seen = .false.
            do i = 1, nb
                if (clsb(i, 1) > 0) seen = .true.
                call check(error, .not. (seen .and. clsb(i, 1) == 0), &
                           'overturning monotone in amplitude')
                if (allocated(error)) return
            end do
            call check(error, seen .and. clsb(1, 1) == 0, 'both classes present')
            if (allocated(error)) return
        end do
        ! a 30 x 30 one-sine map runs (timing of the 200 x 200 map: see the report)
        block
            real(dp) :: a30(30), f30(30)
            integer :: c30(30, 30)
            do i = 1, 30
                a30(i) = 1.0_dp + 0.5_dp * real(i - 1, dp)
                f30(i) = 0.5_dp + 0.4_dp * real(i - 1, dp)
            end do
            call overturning_map(0.25_dp, 0.9_dp, PULSE_SINE_CYCLE, f30, a30, c30, stat, msg)
            call check(error, stat, SEISPULSE_SUCCESS, '30 x 30 map ('//trim(msg)//')')
            if (allocated(error)) return
            call check(error, all(c30 >= 0 .and. c30 <= 3), 'every cell decided')
        end block
    end subroutine test_maps

    !> Grid output and outcome fields.
    subroutine test_grid_outcomes(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        real(dp) :: tg(5), th(5), om(5), alpha
        alpha = 0.2_dp
        blk = make_block(alpha, 2.0_dp, 0.9_dp, .false.)
        ! below the threshold: no uplift
        call run_ok(error, blk, sine_cycle_pulse(0.99_dp * g0 * tan(alpha), 1.0_dp), run, &
                    'no uplift')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_NO_UPLIFT, 'no uplift')
        if (allocated(error)) return
        call check(error, ieee_is_nan(run%t_uplift) .and. ieee_is_nan(run%t_overturn), &
                   'NaN times without uplift')
        if (allocated(error)) return
        ! strong long rectangle: overturns without impact; on its side afterwards
        tg = [-1.0_dp, 0.0_dp, 0.3_dp, 30.0_dp, 60.0_dp]
        call run_ok(error, blk, rectangular_pulse(3.0_dp * g0 * tan(alpha), 5.0_dp), run, &
                    'overturn', tg, th, om)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_OVERTURN_NO_IMPACT, 'overturns')
        if (allocated(error)) return
        call check(error, run%t_overturn < run%t_end .and. run%t_end < 30.0_dp, &
                   'alpha crossed before pi/2')
        if (allocated(error)) return
        call check(error, th(1), 0.0_dp, message='at rest before t = 0')
        if (allocated(error)) return
        call check(error, th(3) > 0.0_dp .and. th(3) < alpha, 'rocking at 0.3 s')
        if (allocated(error)) return
        call check(error, th(4), pi / 2.0_dp, message='on its side')
        if (allocated(error)) return
        call check(error, run%theta_max, pi / 2.0_dp, rtol=1.0e-12_dp, message='theta_max')
        if (allocated(error)) return
        ! negative pulse: the other side
        call run_ok(error, blk, rectangular_pulse(-3.0_dp * g0 * tan(alpha), 5.0_dp), run, &
                    'overturn negative', tg, th, om)
        if (allocated(error)) return
        call check(error, th(5), -pi / 2.0_dp, message='on the other side')
        if (allocated(error)) return
        call check(error, run%theta_min, -pi / 2.0_dp, rtol=1.0e-12_dp, message='theta_min')
        if (allocated(error)) return
        ! initial state beyond the barrier, no excitation: falls over at once
        call run_ok(error, blk, rectangular_pulse(0.0_dp, 1.0_dp), run, 'released beyond', &
                    theta0=1.05_dp * alpha)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_OVERTURN_NO_IMPACT, 'released beyond alpha')
        if (allocated(error)) return
        ! released inside: comes to rest, grid 0 after t_end
        tg = [0.0_dp, 0.1_dp, 0.2_dp, 50.0_dp, 60.0_dp]
        call run_ok(error, blk, rectangular_pulse(0.0_dp, 1.0_dp), run, 'released inside', &
                    tg, th, om, theta0=0.9_dp * alpha)
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_REST, 'released inside: rest')
        if (allocated(error)) return
        call check(error, th(1), 0.9_dp * alpha, message='initial state on the grid')
        if (allocated(error)) return
        call check(error, run%t_end < 50.0_dp .and. abs(th(4)) + abs(om(4)) < tiny(1.0_dp), &
                   'rest on the grid')
        if (allocated(error)) return
        call check(error, run%t_uplift, 0.0_dp, message='t_uplift of an initial state')
        if (allocated(error)) return
        ! e = 1 without t_max: perpetual rocking, stopped at the decision
        blk%e = 1.0_dp
        call run_ok(error, blk, sine_cycle_pulse(1.05_dp * g0 * tan(alpha), 1.0_dp), run, 'e = 1')
        if (allocated(error)) return
        call check(error, run%outcome, ROCK_RUN_TIME_LIMIT, 'e = 1 safe: time limit')
    end subroutine test_grid_outcomes

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        type(pulse_t) :: pl
        integer :: stat, cls(2, 2)
        character(len=200) :: msg
        real(dp) :: nan, tg(3), th(3), om(2)
        nan = ieee_value(nan, ieee_quiet_nan)
        pl = sine_cycle_pulse(1.0_dp, 1.0_dp)
        call expect_rect(-1.0_dp, 1.0_dp, 'b')
        if (allocated(error)) return
        call expect_rect(1.0_dp, 0.0_dp, 'h')
        if (allocated(error)) return
        call expect_rect(nan, 1.0_dp, 'b')
        if (allocated(error)) return
        call symmetric_block(1.0_dp, 0.2_dp, 0.5_dp, g0, blk, stat, msg)
        call expect('io_over_mr2')
        if (allocated(error)) return
        call symmetric_block(1.0_dp, 2.0_dp, 1.5_dp, g0, blk, stat, msg)
        call expect('alpha')
        if (allocated(error)) return
        blk = make_block(0.2_dp, 2.0_dp, 1.5_dp, .false.)
        call rock_pulse(blk, pl, run, stat, msg)
        call expect('e')
        if (allocated(error)) return
        blk = make_block(0.2_dp, 2.0_dp, -0.1_dp, .false.)
        call rock_pulse(blk, pl, run, stat, msg)
        call expect('e')
        if (allocated(error)) return
        blk = make_block(nan, 2.0_dp, 0.9_dp, .false.)
        call rock_pulse(blk, pl, run, stat, msg)
        call expect('alpha')
        if (allocated(error)) return
        blk = make_block(pi / 2.0_dp, 2.0_dp, 0.9_dp, .false.)
        call rock_pulse(blk, pl, run, stat, msg)
        call expect('alpha')
        if (allocated(error)) return
        blk = make_block(0.2_dp, nan, 0.9_dp, .false.)
        call rock_pulse(blk, pl, run, stat, msg)
        call expect('p')
        if (allocated(error)) return
        blk = make_block(0.2_dp, 2.0_dp, 0.9_dp, .false.)
        call rock_record(blk, [1.0_dp, 2.0_dp], 0.0_dp, g0, run, stat, msg)
        call expect('dt')
        if (allocated(error)) return
        call rock_record(blk, [1.0_dp, 2.0_dp], nan, g0, run, stat, msg)
        call expect('dt')
        if (allocated(error)) return
        call rock_record(blk, [1.0_dp, nan], 0.01_dp, g0, run, stat, msg)
        call expect('accel(2)')
        if (allocated(error)) return
        call rock_record(blk, [1.0_dp, 2.0_dp], 0.01_dp, 0.0_dp, run, stat, msg)
        call expect('g')
        if (allocated(error)) return
        call rock_record(blk, [1.0_dp, 2.0_dp], 0.01_dp, nan, run, stat, msg)
        call expect('g')
        if (allocated(error)) return
        call rock_record(blk, [1.0_dp, huge(1.0_dp)], 0.01_dp, g0, run, stat, msg)
        call expect('accel(2)')
        if (allocated(error)) return
        tg = [0.0_dp, 1.0_dp, 2.0_dp]
        call rock_pulse(blk, pl, run, stat, msg, tg, th, om)
        call expect('omega_grid')
        if (allocated(error)) return
        call rock_pulse(blk, pl, run, stat, msg, theta0=2.0_dp)
        call expect('theta0')
        if (allocated(error)) return
        call rock_pulse(blk, pl, run, stat, msg, t_max=nan)
        call expect('t_max')
        if (allocated(error)) return
        call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp, -1.0_dp], &
                             [1.0_dp, 2.0_dp], cls, stat, msg)
        call expect('freq_ratio(2)')
        if (allocated(error)) return
        call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp, 2.0_dp], &
                             [1.0_dp, nan], cls, stat, msg)
        call expect('amp_ratio(2)')
        if (allocated(error)) return
        call overturning_map(0.2_dp, 0.9_dp, PULSE_MP, [1.0_dp, 2.0_dp], &
                             [1.0_dp, 2.0_dp], cls, stat, msg)
        call expect('kind')
        if (allocated(error)) return
        call overturning_map(0.2_dp, 2.0_dp, PULSE_SINE_CYCLE, [1.0_dp, 2.0_dp], &
                             [1.0_dp, 2.0_dp], cls, stat, msg)
        call expect('e')
        if (allocated(error)) return
        call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp], &
                             [1.0_dp, 2.0_dp], cls, stat, msg)
        call expect('classes')
    contains
        subroutine expect_rect(b, h, name)
            real(dp), intent(in) :: b, h
            character(len=*), intent(in) :: name
            call rectangular_block(b, h, g0, blk, stat, msg)
            call expect(name)
        end subroutine expect_rect
        subroutine expect(name)
            character(len=*), intent(in) :: name
            call check(error, stat, SEISPULSE_INVALID_INPUT, name//': status')
            if (allocated(error)) return
            call check(error, index(msg, name) == 1, 'message must start with '//name// &
                       ', got: '//trim(msg))
            msg = ''
        end subroutine expect
    end subroutine test_bad_input

    ! ---------------------------------------------------------------- vertical (section 7)

    !> Two runs equal bit for bit (every field the run reports).
    subroutine identical_run(error, a, b, label)
        type(test_error), allocatable, intent(inout) :: error
        type(rocking_run_t), intent(in) :: a, b
        character(len=*), intent(in) :: label
        logical :: same
        same = a%outcome == b%outcome .and. a%n_impacts == b%n_impacts .and. &
               a%n_steps == b%n_steps
        if (same) same = all(same_bits_v([a%t_end, a%theta_max, a%theta_min, a%t_uplift, &
                                          a%t_overturn, a%t_impacts], &
                                         [b%t_end, b%theta_max, b%theta_min, b%t_uplift, &
                                          b%t_overturn, b%t_impacts]))
        call check(error, same, label//': runs differ')
    contains
        elemental logical function same_bits_v(x, y)
            real(dp), intent(in) :: x, y
            same_bits_v = same_bits(x, y)
        end function same_bits_v
    end subroutine identical_run

    !> (a) kv = 0 and a vertical record of zeros take the horizontal-only results bit for
    !> bit (pulses, records, maps; nonlinear and linearized).
    subroutine test_vertical_identity(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: r0, r1
        type(pulse_t) :: pl
        real(dp) :: acc(61), zero(61), tg(50), th0(50), th1(50), om0(50), om1(50)
        integer :: stat, i, j, c0(3, 4), c1(3, 4)
        logical :: lin
        character(len=200) :: msg
        do i = 1, size(acc)
            acc(i) = 0.6_dp * sin(real(i - 1, dp) * 0.21_dp)
            zero(i) = 0.0_dp
        end do
        do i = 1, size(tg)
            tg(i) = 0.05_dp * real(i, dp)
        end do
        do j = 1, 2
            lin = j == 2
            blk = make_block(0.2_dp, 2.0_dp, 0.9_dp, lin)
            pl = sine_cycle_pulse(3.0_dp * g0 * tan(0.2_dp), 2.0_dp * pi / 6.0_dp)
            call rock_pulse(blk, pl, r0, stat, msg, tg, th0, om0)
            call rock_pulse(blk, pl, r1, stat, msg, tg, th1, om1, kv=0.0_dp)
            call identical_run(error, r0, r1, 'pulse, kv = 0')
            if (allocated(error)) return
            call check(error, th1, th0, rtol=0.0_dp, message='pulse grid, kv = 0')
            if (allocated(error)) return
            call check(error, om1, om0, rtol=0.0_dp, message='pulse grid, kv = 0')
            if (allocated(error)) return
            call rock_record(blk, acc, 0.02_dp, g0, r0, stat, msg, tg, th0, om0)
            call check(error, r0%n_impacts >= 2, 'the test record makes the block impact')
            if (allocated(error)) return
            call rock_record(blk, acc, 0.02_dp, g0, r1, stat, msg, tg, th1, om1, accel_v=zero)
            call check(error, stat, SEISPULSE_SUCCESS, 'zero accel_v: status')
            if (allocated(error)) return
            call identical_run(error, r0, r1, 'record, accel_v = 0')
            if (allocated(error)) return
            call check(error, th1, th0, rtol=0.0_dp, message='record grid, accel_v = 0')
            if (allocated(error)) return
            call check(error, om1, om0, rtol=0.0_dp, message='record grid, accel_v = 0')
            if (allocated(error)) return
            call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp, 2.0_dp, 4.0_dp, &
                                 8.0_dp], [1.5_dp, 3.0_dp, 6.0_dp], c0, stat, linearized=lin)
            call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp, 2.0_dp, 4.0_dp, &
                                 8.0_dp], [1.5_dp, 3.0_dp, 6.0_dp], c1, stat, linearized=lin, &
                                 kv=0.0_dp)
            call check(error, all(c0 == c1), 'map, kv = 0')
            if (allocated(error)) return
        end do
    end subroutine test_vertical_identity

    !> (b), (e) With a_v = c constant, doc/rocking.md (R.9) is
    !> theta'' = -p^2 (1 + c/g) [sin(alpha s - theta) - a_g/(g + c) cos(alpha s - theta)]:
    !> the block with p'^2 = p^2 (1 + c/g) and gravity g' = g + c under the same a_g (m/s^2),
    !> uplift at a_g > (g + c) tan(alpha) included. Checked while the excitation lasts
    !> (afterwards a_v = 0): a record with a constant vertical, and a rectangular pulse with
    !> kv (a_v = kv A on the pulse); nonlinear and linearized (the same rescaling).
    subroutine test_vertical_constant(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk, blk2
        type(rocking_run_t) :: ra, rb
        real(dp) :: acc(201), vert(201), tg(40), tha(40), thb(40), oma(40), omb(40)
        real(dp) :: dt, c, amp, kv, td
        integer :: stat, i, j, k
        character(len=200) :: msg
        dt = 0.01_dp
        do i = 1, size(acc)
            acc(i) = 0.5_dp * sin(real(i - 1, dp) * 0.08_dp)   ! in g: up to 0.5 g
        end do
        do i = 1, size(tg)
            tg(i) = 0.05_dp * real(i, dp)          ! up to 2 s = the end of the record
        end do
        do j = 1, 4
            blk = make_block(0.18_dp, 2.0_dp, 0.85_dp, j > 2)
            ! c = -0.3 g (lighter) and +0.4 g (heavier)
            c = -0.3_dp * g0
            if (mod(j, 2) == 0) c = 0.4_dp * g0
            vert = c / g0
            msg = ''
            call rock_record(blk, acc, dt, g0, ra, stat, msg, tg, tha, oma, accel_v=vert)
            call check(error, stat, SEISPULSE_SUCCESS, 'constant vertical ('//trim(msg)//')')
            if (allocated(error)) return
            call check(error, maxval(abs(tha)) > 1.0e-3_dp, 'the test record rocks the block')
            if (allocated(error)) return
            blk2 = blk
            blk2%g = g0 + c
            blk2%p = blk%p * sqrt(1.0_dp + c / g0)
            ! the same a_g in m/s^2: samples g0 acc in units of 1 m/s^2
            call rock_record(blk2, g0 * acc, dt, 1.0_dp, rb, stat, msg, tg, thb, omb)
            call check(error, stat, SEISPULSE_SUCCESS, 'rescaled block')
            if (allocated(error)) return
            call check(error, ra%t_uplift, rb%t_uplift, rtol=1.0e-12_dp, &
                       message='constant vertical: uplift')
            if (allocated(error)) return
            do k = 1, min(ra%n_impacts, rb%n_impacts)
                if (rb%t_impacts(k) > 2.0_dp) exit
                call check(error, ra%t_impacts(k), rb%t_impacts(k), rtol=1.0e-9_dp, &
                           message='constant vertical: impact time')
                if (allocated(error)) return
            end do
            do k = 1, size(tg)
                call check(error, tha(k), thb(k), rtol=1.0e-8_dp, atol=1.0e-10_dp, &
                           message='constant vertical: theta')
                if (allocated(error)) return
                call check(error, oma(k), omb(k), rtol=1.0e-8_dp, atol=1.0e-10_dp, &
                           message='constant vertical: omega')
                if (allocated(error)) return
            end do
            ! rectangular pulse with kv: a_v = kv amp while it lasts
            kv = c / g0
            td = 1.2_dp
            amp = 1.8_dp * g0 * tan(0.18_dp) * (1.0_dp + kv)
            call rock_pulse(blk, rectangular_pulse(amp, td), ra, stat, msg, tg(1:24), &
                            tha(1:24), oma(1:24), kv=kv)
            call check(error, stat, SEISPULSE_SUCCESS, 'kv pulse ('//trim(msg)//')')
            if (allocated(error)) return
            blk2%g = g0 + kv * amp
            blk2%p = blk%p * sqrt(1.0_dp + kv * amp / g0)
            call rock_pulse(blk2, rectangular_pulse(amp, td), rb, stat, msg, tg(1:24), &
                            thb(1:24), omb(1:24))
            call check(error, ra%t_uplift, rb%t_uplift, atol=1.0e-14_dp, &
                       message='kv pulse: uplift')
            if (allocated(error)) return
            call check(error, maxval(abs(thb(1:24))) > 1.0e-3_dp, 'kv pulse: the block rocks')
            if (allocated(error)) return
            do k = 1, 24
                call check(error, tha(k), thb(k), rtol=1.0e-8_dp, atol=1.0e-10_dp, &
                           message='kv pulse: theta')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_vertical_constant

    !> (c), (e) Uplift from rest: a rectangular pulse of amplitude 1 +- 1e-6 times the
    !> thresholds (R.11), g tan(alpha)/(1 - kv tan(alpha)) on side +1 and
    !> g tan(alpha)/(1 + kv tan(alpha)) on side -1 (alpha for tan(alpha) when linearized),
    !> uplifts at t = 0 or never; kv tan(alpha) >= 1: never on side +1. On a record with a
    !> constant a_g = A and a_v from v0 to v1 (linear), the uplift is where
    !> s A = (g + a_v) tan(alpha), (R.10), in closed form.
    subroutine test_vertical_uplift(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        real(dp) :: alpha, tu, kv, thr, acc(11), vert(11), dt, v0, v1, a, t_ex
        integer :: stat, j, s, m
        character(len=200) :: msg
        alpha = 0.25_dp
        do j = 1, 4
            blk = make_block(alpha, 2.0_dp, 0.9_dp, j > 2)
            tu = tan(alpha)
            if (j > 2) tu = alpha
            kv = 0.6_dp
            if (mod(j, 2) == 0) kv = -0.45_dp
            do s = 1, -1, -2
                thr = g0 * tu / (1.0_dp - real(s, dp) * kv * tu)
                call rock_pulse(blk, rectangular_pulse(real(s, dp) * thr * (1.0_dp + 1.0e-6_dp), &
                                0.5_dp), run, stat, msg, kv=kv)
                call check(error, run%outcome /= ROCK_RUN_NO_UPLIFT .and. .not. run%t_uplift > 0.0_dp, &
                           'just above the threshold: uplift at 0')
                if (allocated(error)) return
                call check(error, s * run%theta_max + s * run%theta_min > 0.0_dp, &
                           'uplift on side s')
                if (allocated(error)) return
                call rock_pulse(blk, rectangular_pulse(real(s, dp) * thr * (1.0_dp - 1.0e-6_dp), &
                                0.5_dp), run, stat, msg, kv=kv)
                call check(error, run%outcome, ROCK_RUN_NO_UPLIFT, 'just below: no uplift')
                if (allocated(error)) return
                ! and kv = 0 uplifts below it when kv s > 0 (the threshold moved)
                call rock_pulse(blk, rectangular_pulse(real(s, dp) * g0 * tu * 1.001_dp, &
                                0.5_dp), run, stat, msg, kv=kv)
                if (s * kv > 0.0_dp) then
                    call check(error, run%outcome, ROCK_RUN_NO_UPLIFT, 'kv s > 0 raises it')
                else
                    call check(error, run%outcome /= ROCK_RUN_NO_UPLIFT, 'kv s < 0 lowers it')
                end if
                if (allocated(error)) return
            end do
            ! kv tan(alpha) >= 1: side +1 never, whatever the amplitude
            call rock_pulse(blk, rectangular_pulse(50.0_dp * g0, 0.5_dp), run, stat, msg, &
                            kv=1.0_dp / tu)
            call check(error, stat, SEISPULSE_SUCCESS, 'kv tan(alpha) = 1: status')
            if (allocated(error)) return
            call check(error, run%outcome, ROCK_RUN_NO_UPLIFT, 'kv tan(alpha) = 1: no uplift')
            if (allocated(error)) return
            ! record: A = g tu (the threshold at a_v = 0), a_v from v0 to v1 on 10 steps
            m = 10
            dt = 0.03_dp
            do s = 1, -1, -2
                v0 = 0.2_dp
                v1 = -0.3_dp
                ! in g: uplift where 1.13 = 1 + a_v/g, inside the second sample step (t =
                ! 1.4 dt), so the root is located inside a step, not found at a sample
                a = real(s, dp) * tu * 1.13_dp
                acc = a
                do m = 1, 11
                    vert(m) = v0 + (v1 - v0) * real(m - 1, dp) / 10.0_dp
                end do
                call rock_record(blk, acc, dt, g0, run, stat, msg, accel_v=vert)
                call check(error, stat, SEISPULSE_SUCCESS, 'vertical record: status')
                if (allocated(error)) return
                ! 1 + v(t) = 1.13: v = 0.13 at t = 10 dt (v0 - 0.13)/(v0 - v1)
                t_ex = 10.0_dp * dt * (v0 - 0.13_dp) / (v0 - v1)
                call check(error, run%t_uplift, t_ex, rtol=1.0e-12_dp, &
                           message='vertical record: uplift time')
                if (allocated(error)) return
                call check(error, s * run%theta_max + s * run%theta_min > 0.0_dp, &
                           'vertical record: side s')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_vertical_uplift

    !> (d) a_v < -g is an input error naming kv (with the time), accel_v(i), or kv and
    !> amp_ratio(i) in a map; a_v = -g exactly is allowed.
    subroutine test_vertical_bad(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: run
        real(dp) :: acc(5), vert(5), nan
        integer :: stat, cls(2, 1)
        character(len=300) :: msg
        nan = ieee_value(nan, ieee_quiet_nan)
        blk = make_block(0.2_dp, 2.0_dp, 0.9_dp, .false.)
        ! sine cycle of 0.5 g: kv = 2.5 gives -1.25 g on the negative lobe (at t = 0.75)
        msg = ''
        call rock_pulse(blk, sine_cycle_pulse(0.5_dp * g0, 1.0_dp), run, stat, msg, kv=2.5_dp)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'kv: status')
        if (allocated(error)) return
        call check(error, index(msg, 'kv = 2.5') == 1 .and. index(msg, 't = 0.75') > 0, &
                   'kv message: '//trim(msg))
        if (allocated(error)) return
        ! kv = 2: -g exactly, allowed
        call rock_pulse(blk, sine_cycle_pulse(0.5_dp * g0, 1.0_dp), run, stat, msg, kv=2.0_dp)
        call check(error, stat, SEISPULSE_SUCCESS, 'kv a_g = -g: allowed')
        if (allocated(error)) return
        call rock_pulse(blk, sine_cycle_pulse(0.5_dp * g0, 1.0_dp), run, stat, msg, kv=nan)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'kv') == 1, &
                   'kv = NaN: '//trim(msg))
        if (allocated(error)) return
        acc = 0.1_dp
        vert = [0.0_dp, -0.5_dp, -1.01_dp, 0.0_dp, 0.0_dp]
        msg = ''
        call rock_record(blk, acc, 0.01_dp, g0, run, stat, msg, accel_v=vert)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel_v(3)') == 1, &
                   'accel_v below -g: '//trim(msg))
        if (allocated(error)) return
        msg = ''
        call rock_record(blk, acc, 0.01_dp, g0, run, stat, msg, accel_v=vert(1:4))
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel_v') == 1, &
                   'accel_v size: '//trim(msg))
        if (allocated(error)) return
        vert(3) = nan
        msg = ''
        call rock_record(blk, acc, 0.01_dp, g0, run, stat, msg, accel_v=vert)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'accel_v') == 1, &
                   'accel_v NaN: '//trim(msg))
        if (allocated(error)) return
        ! map: amp_ratio(2) tan(alpha) kv = 3 tan(0.2) 2 > 1 on the negative lobe
        msg = ''
        call overturning_map(0.2_dp, 0.9_dp, PULSE_SINE_CYCLE, [1.0_dp], [1.0_dp, 3.0_dp], &
                             cls, stat, msg, kv=2.0_dp)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'kv = 2') == 1 &
                   .and. index(msg, 'amp_ratio(2)') > 0, 'map kv: '//trim(msg))
    end subroutine test_vertical_bad

end module test_rocking_sim
