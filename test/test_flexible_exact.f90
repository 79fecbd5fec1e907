!> Flexible sliding masses, exact (seispulse_flexible_exact): the modal recurrence against
!> closed forms for step and ramp input (positive, negative, critical, over-damping); the
!> coupled model without sliding against the modal response; the coupled model against
!> an independent integration written here (RK4 on sub-steps, events by bisection on the
!> re-integrated sub-step) on a synthetic record and on a short soft mass with many short
!> slides, and unchanged by linear upsampling; its rigid limit (Vs -> infinity) against
!> newmark_rigid(exact) and, under a sampled exponential pulse, the closed form of
!> seispulse_sliding_closed; yield tables (rigid exact and slammer, coupled) against
!> independent integrations and the constant yield; the dispatch of seispulse_flexible;
!> the first-zero search on a function with close zeros; bad input.
module test_flexible_exact
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_flexible_exact, only: modal_response_exact, coupled_exact, zero_function, &
                                        first_zero
    use seispulse_pulses, only: exp_pulse
    use seispulse_sliding_closed, only: half_cycle_t, half_cycle
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t, FLEX_EXACT
    use seispulse_flexible, only: flexible_decoupled, flexible_coupled
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, NEWMARK_EXACT, &
                                 NEWMARK_SLAMMER
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_flexible_exact

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp
    real(dp), parameter :: d1 = 1.0_dp - 8.0_dp / pi**2

    !> f(x) = (x - 0.3)^2 (x - 0.31)^2 + eps_dip - 1e-6 x: two close zeros near 0.3 (test).
    type, extends(zero_function) :: dip_t
        real(dp) :: lift = 0.0_dp
    contains
        procedure :: taylor => dip_taylor
    end type dip_t

contains

    subroutine collect_flexible_exact(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('modal recurrence = closed forms (step, ramp)', test_modal_closed), &
                 new_unittest('coupled without sliding = modal response', test_coupled_no_slide), &
                 new_unittest('coupled = independent RK4 with events (record)', &
                              test_coupled_reference), &
                 new_unittest('coupled = independent RK4: short soft mass, many slides', &
                              test_coupled_many_slides), &
                 new_unittest('coupled: linear upsampling of the record changes nothing', &
                              test_coupled_upsampling), &
                 new_unittest('coupled -> rigid exact as Vs grows', test_coupled_rigid_limit), &
                 new_unittest('decoupled (rigid exact on HEA) -> rigid exact as Vs grows', &
                              test_decoupled_rigid_limit), &
                 new_unittest('stiff mass under a sampled exponential pulse: closed form', &
                              test_pulse_closed_form), &
                 new_unittest('first_zero: close double zero, touch, none', test_first_zero), &
                 new_unittest('rigid ky table, one row = constant ky (bitwise)', &
                              test_table_one_row), &
                 new_unittest('rigid ky table, equal rows = constant ky', test_table_flat), &
                 new_unittest('rigid ky table: a long run-out after the record', &
                              test_table_long_runout), &
                 new_unittest('rigid ky table, exact = independent RK4 with events', &
                              test_table_reference), &
                 new_unittest('rigid ky table, slammer = RigidBlock rule written here', &
                              test_table_slammer), &
                 new_unittest('coupled ky table: one row = constant ky (bitwise)', &
                              test_coupled_table_one_row), &
                 new_unittest('coupled ky table: equal rows = constant ky', &
                              test_coupled_table_flat), &
                 new_unittest('coupled ky table = independent RK4 with events', &
                              test_coupled_table_reference), &
                 new_unittest('flexible_decoupled(exact) = rigid exact on the HEA (bitwise)', &
                              test_dispatch_decoupled), &
                 new_unittest('flexible_coupled(exact) = coupled_exact (bitwise)', &
                              test_dispatch_coupled), &
                 new_unittest('coupled: zeros appended to the record change nothing', &
                              test_coupled_zero_padding), &
                 new_unittest('coupled: stiff masses (omega 1.6e6, 1.6e7, H = 1e-5 m)', &
                              test_coupled_stiff), &
                 new_unittest('modal response: overflow is a status', test_modal_overflow), &
                 new_unittest('first_zero: a bound that is not finite proves nothing', &
                              test_first_zero_inf), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input)]
    end subroutine collect_flexible_exact

    ! ---------------------------------------------------------------- helpers

    !> A deterministic strong-motion-like record (g).
    function synthetic(n, dt, seed) result(a)
        integer, intent(in) :: n, seed
        real(dp), intent(in) :: dt
        real(dp) :: a(n), t, env
        integer :: i, k
        real(dp), parameter :: freq(4) = [0.9_dp, 2.1_dp, 3.7_dp, 6.3_dp]
        real(dp), parameter :: amp(4) = [0.15_dp, 0.22_dp, 0.12_dp, 0.06_dp]
        do i = 1, n
            t = real(i - 1, dp) * dt
            env = (t / 2.5_dp)**2 * exp(2.0_dp - 2.0_dp * t / 2.5_dp)
            a(i) = 0.0_dp
            do k = 1, 4
                a(i) = a(i) + amp(k) * sin(2.0_dp * pi * freq(k) * t + 0.41_dp * k * seed)
            end do
            a(i) = 1.5_dp * env * a(i)
        end do
    end function synthetic

    !> The piecewise-linear record at t (s), 0 after the last sample.
    pure real(dp) function record_at(accel, dt, t) result(a)
        real(dp), intent(in) :: accel(:), dt, t
        integer :: i
        real(dp) :: r
        i = int(t / dt) + 1
        if (i >= size(accel)) then
            a = 0.0_dp
            return
        end if
        r = min(max(t / dt - real(i - 1, dp), 0.0_dp), 1.0_dp)
        a = accel(i) + (accel(i + 1) - accel(i)) * r
    end function record_at

    !> Independent integration of the coupled model: classical RK4 on m sub-steps per
    !> sample step, events (HEA = g ky, s' = 0) located by bisection on the sub-step
    !> re-integrated from its start; after the record a = 0 until the mass is at rest and
    !> the stuck beam's energy bound (2/pi) sqrt(omega^2 u'^2 + u''^2) < g ky (F.48).
    subroutine reference_coupled(accel, dt, g, omega, xi, ky, m, s_end, s_hist, u_hist, kd, kv)
        real(dp), intent(in) :: accel(:), dt, g, omega, xi, ky
        integer, intent(in) :: m
        real(dp), intent(out) :: s_end
        real(dp), intent(out) :: s_hist(:), u_hist(:)
        real(dp), intent(in), optional :: kd(:), kv(:)
        real(dp) :: y(4), y1(4), hs, t, tl, th, tm, ym(4), rest
        integer :: i, j, k, n, it
        logical :: slide
        n = size(accel)
        hs = dt / m
        y = 0.0_dp
        slide = hea_of(y, 0.0_dp, .false.) > g * kys(y(3))
        s_hist(1) = 0.0_dp
        u_hist(1) = 0.0_dp
        i = 0
        do k = 1, 100000000
            i = i + 1
            if (i > n - 1 .and. .not. slide) then
                if (2.0_dp / pi * sqrt(omega**2 * y(2)**2 + (-2.0_dp * xi * omega * y(2) &
                    - omega**2 * y(1))**2) < g * kys(y(3))) exit
            end if
            do j = 0, m - 1
                t = real(i - 1, dp) * dt + j * hs
                rest = hs
                do it = 1, 4
                    y1 = rk4(y, t, rest, slide)
                    if (.not. slide .and. hea_of(y1, t + rest, .false.) > g * kys(y(3))) then
                        call locate(.false.)
                    else if (slide .and. y1(4) < 0.0_dp) then
                        call locate(.true.)
                    else
                        y = y1
                        exit
                    end if
                end do
            end do
            if (i <= n - 1) then
                s_hist(i + 1) = y(3)
                u_hist(i + 1) = y(1)
            end if
        end do
        s_end = y(3)
    contains
        !> The event inside [t, t + rest]: bisection on the partial step, then the phase
        !> switches there and the rest of the sub-step is integrated by the next pass.
        subroutine locate(stop_event)
            logical, intent(in) :: stop_event
            integer :: b
            tl = 0.0_dp
            th = rest
            do b = 1, 200
                tm = 0.5_dp * (tl + th)
                if (.not. (tm > tl .and. tm < th)) exit
                ym = rk4(y, t, tm, slide)
                if (stop_event) then
                    if (ym(4) < 0.0_dp) then
                        th = tm
                    else
                        tl = tm
                    end if
                else
                    if (hea_of(ym, t + tm, .false.) > g * kys(y(3))) then
                        th = tm
                    else
                        tl = tm
                    end if
                end if
            end do
            y = rk4(y, t, th, slide)
            if (stop_event) y(4) = 0.0_dp
            slide = .not. slide
            t = t + th
            rest = rest - th
        end subroutine locate

        real(dp) function acc_at(tt)
            real(dp), intent(in) :: tt
            acc_at = record_at(accel, dt, tt)
        end function acc_at

        !> ky (g) at s (m): the constant, or the table interpolated.
        real(dp) function kys(ss)
            real(dp), intent(in) :: ss
            integer :: l
            kys = ky
            if (.not. present(kd)) return
            kys = kv(size(kv))
            do l = 1, size(kd) - 1
                if (ss < kd(l + 1)) then
                    kys = kv(l) + (kv(l + 1) - kv(l)) * (ss - kd(l)) / (kd(l + 1) - kd(l))
                    return
                end if
            end do
        end function kys

        real(dp) function hea_of(yy, tt, sl)
            real(dp), intent(in) :: yy(4), tt
            logical, intent(in) :: sl
            real(dp) :: acc, a
            a = acc_at(tt)
            if (sl) then
                acc = (-4.0_dp / pi * g * kys(yy(3)) - 2.0_dp * xi * omega * yy(2) &
                       - omega**2 * yy(1)) / d1
            else
                acc = -4.0_dp / pi * g * a - 2.0_dp * xi * omega * yy(2) - omega**2 * yy(1)
            end if
            hea_of = g * a + 2.0_dp / pi * acc
        end function hea_of

        function rhs(yy, tt, sl) result(f)
            real(dp), intent(in) :: yy(4), tt
            logical, intent(in) :: sl
            real(dp) :: f(4), a
            a = acc_at(tt)
            f(1) = yy(2)
            if (sl) then
                f(2) = (-4.0_dp / pi * g * kys(yy(3)) - 2.0_dp * xi * omega * yy(2) &
                        - omega**2 * yy(1)) / d1
                f(3) = yy(4)
                f(4) = g * a - g * kys(yy(3)) + 2.0_dp / pi * f(2)
            else
                f(2) = -4.0_dp / pi * g * a - 2.0_dp * xi * omega * yy(2) - omega**2 * yy(1)
                f(3) = 0.0_dp
                f(4) = 0.0_dp
            end if
        end function rhs

        !> One RK4 step of length hh from (tt, yy); the record is linear on the step
        !> (the sub-steps never cross a sample), evaluated at its own times.
        function rk4(yy, tt, hh, sl) result(yn)
            real(dp), intent(in) :: yy(4), tt, hh
            logical, intent(in) :: sl
            real(dp) :: yn(4), k1(4), k2(4), k3(4), k4(4)
            k1 = rhs(yy, tt, sl)
            k2 = rhs(yy + 0.5_dp * hh * k1, tt + 0.5_dp * hh, sl)
            k3 = rhs(yy + 0.5_dp * hh * k2, tt + 0.5_dp * hh, sl)
            k4 = rhs(yy + hh * k3, tt + hh, sl)
            yn = yy + hh / 6.0_dp * (k1 + 2.0_dp * k2 + 2.0_dp * k3 + k4)
        end function rk4
    end subroutine reference_coupled

    subroutine run_coupled(error, accel, dt, omega, xi, ky, smax, sfin, tend, label, s_hist, &
                           u_hist, kd, kv, v_hist)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: accel(:), dt, omega, xi, ky
        real(dp), intent(out) :: smax, sfin, tend
        character(len=*), intent(in) :: label
        real(dp), intent(out), optional :: s_hist(:), u_hist(:), v_hist(:)
        real(dp), intent(in), optional :: kd(:), kv(:)
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call coupled_exact(accel, dt, g0, omega, xi, ky, smax, sfin, tend, stat, msg, &
                           ky_disp=kd, ky_values=kv, s_hist=s_hist, sdot_hist=v_hist, &
                           u_modal=u_hist)
        call check(error, stat, SEISPULSE_SUCCESS, label//': status ('//trim(msg)//')')
    end subroutine run_coupled

    ! ---------------------------------------------------------------- tests

    !> From rest, a = A for t >= 0 (a step at the first sample) and a = r t (a ramp):
    !> u(t) in closed form, for damping 0.05, -0.1 and 0.7 (F.30).
    subroutine test_modal_closed(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 801
        real(dp), parameter :: dt = 0.005_dp, omega = 2.0_dp * pi / 0.37_dp
        real(dp) :: a(n), u(n), hea(n), ue(n), t, wd, kk, c1, c2, w2, cc, up0
        real(dp), parameter :: xis(3) = [0.05_dp, -0.1_dp, 0.7_dp]
        real(dp) :: l1, l2
        integer :: i, j, stat
        ! over-damped and critical step responses:
        ! u = K/w2 (1 + (l2 e^(l1 t) - l1 e^(l2 t))/(l1 - l2))
        do j = 1, 2
            a = 0.2_dp
            kk = -4.0_dp / pi * g0 * 0.2_dp
            if (j == 1) then
                call modal_response_exact(a, dt, g0, omega, 1.5_dp, u, hea, stat)
                l1 = -omega * (1.5_dp - sqrt(1.25_dp))
                l2 = -omega * (1.5_dp + sqrt(1.25_dp))
                ue = [(kk / omega**2 * (1.0_dp + (l2 * exp(l1 * (i - 1) * dt) - l1 &
                       * exp(l2 * (i - 1) * dt)) / (l1 - l2)), i = 1, n)]
            else
                call modal_response_exact(a, dt, g0, omega, 1.0_dp, u, hea, stat)
                ue = [(kk / omega**2 * (1.0_dp - exp(-omega * (i - 1) * dt) * (1.0_dp + omega &
                       * (i - 1) * dt)), i = 1, n)]
            end if
            call check(error, stat, SEISPULSE_SUCCESS, 'over-damped: status')
            if (allocated(error)) return
            call check(error, u, ue, atol=1.0e-13_dp * maxval(abs(ue)), &
                       message='over-damped / critical step response')
            if (allocated(error)) return
        end do
        do j = 1, 3
            wd = omega * sqrt(1.0_dp - xis(j)**2)
            w2 = omega**2
            cc = 2.0_dp * xis(j) * omega
            ! step: u = -(4/pi) g A/w^2 (1 - e^(-xi w t)(cos wd t + xi w/wd sin wd t))
            a = 0.2_dp
            call modal_response_exact(a, dt, g0, omega, xis(j), u, hea, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'step: status')
            if (allocated(error)) return
            kk = -4.0_dp / pi * g0 * 0.2_dp
            do i = 1, n
                t = (i - 1) * dt
                ue(i) = kk / w2 * (1.0_dp - exp(-xis(j) * omega * t) * (cos(wd * t) &
                        + xis(j) * omega / wd * sin(wd * t)))
            end do
            call check(error, u, ue, atol=1.0e-13_dp * maxval(abs(ue)), &
                       message='step response, xi = '//trim(num(xis(j))))
            if (allocated(error)) return
            ! HEA at the first sample: a (1 - 8/pi^2) (u = u' = 0, u'' = -(4/pi) g a)
            call check(error, hea(1), 0.2_dp * d1, rtol=1.0e-15_dp, message='HEA(0)')
            if (allocated(error)) return
            ! ramp a = r t: u = K t/w2 - K c/w2^2 + homogeneous (K = -(4/pi) g r)
            do i = 1, n
                a(i) = 0.3_dp * (i - 1) * dt
            end do
            call modal_response_exact(a, dt, g0, omega, xis(j), u, hea, stat)
            kk = -4.0_dp / pi * g0 * 0.3_dp
            up0 = -kk * cc / w2**2
            c1 = -up0
            c2 = (-kk / w2 + xis(j) * omega * c1) / wd
            do i = 1, n
                t = (i - 1) * dt
                ue(i) = kk * t / w2 + up0 + exp(-xis(j) * omega * t) * (c1 * cos(wd * t) &
                        + c2 * sin(wd * t))
            end do
            call check(error, u, ue, atol=1.0e-13_dp * maxval(abs(ue)), &
                       message='ramp response, xi = '//trim(num(xis(j))))
            if (allocated(error)) return
        end do
    end subroutine test_modal_closed

    !> ky = +inf (huge): the coupled model never slides and its u is the modal response.
    subroutine test_coupled_no_slide(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 2000
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), u(n), hea(n), uc(n), sc(n), smax, sfin, tend, omega
        integer :: stat
        a = synthetic(n, dt, 1)
        omega = pi * 300.0_dp / (2.0_dp * 20.0_dp)
        call modal_response_exact(a, dt, g0, omega, 0.15_dp, u, hea, stat)
        call run_coupled(error, a, dt, omega, 0.15_dp, 1.0e3_dp, smax, sfin, tend, 'no slide', &
                         s_hist=sc, u_hist=uc)
        if (allocated(error)) return
        call check(error, smax, 0.0_dp, atol=0.0_dp, message='no sliding')
        if (allocated(error)) return
        call check(error, uc, u, atol=1.0e-12_dp * maxval(abs(u)), message='u = modal u')
    end subroutine test_coupled_no_slide

    !> A synthetic record, H = 20 m, Vs = 300 m/s, damping 0.2 and 0.02, an over-damped
    !> sliding oscillator (xi = 0.6) and an over-damped mass (xi = 1.2): exact = RK4 with
    !> 400 sub-steps per sample. A negative damping (-0.005) is refused.
    subroutine test_coupled_reference(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), sh(n), uh(n), sr(n), ur(n), smax, sfin, tend, send, omega
        real(dp), parameter :: xis(4) = [0.2_dp, 0.02_dp, 0.6_dp, 1.2_dp]
        integer :: j, stat
        character(len=200) :: msg
        a = synthetic(n, dt, 2)
        omega = pi * 300.0_dp / (2.0_dp * 20.0_dp)
        msg = ''
        call coupled_exact(a, dt, g0, omega, -0.005_dp, 0.12_dp, smax, sfin, tend, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'xi < 0 refused')
        if (allocated(error)) return
        call check(error, index(msg, 'xi') > 0, 'message names xi: '//trim(msg))
        if (allocated(error)) return
        do j = 1, 4
            call run_coupled(error, a, dt, omega, xis(j), 0.12_dp, smax, sfin, tend, 'record', &
                             s_hist=sh, u_hist=uh)
            if (allocated(error)) return
            call reference_coupled(a, dt, g0, omega, xis(j), 0.12_dp, 400, send, sr, ur)
            call check(error, smax > 1.0e-3_dp, 'slides, xi = '//trim(num(xis(j))))
            if (allocated(error)) return
            call check(error, sfin, send, rtol=1.0e-13_dp, message='final s, xi = ' &
                       //trim(num(xis(j))))
            if (allocated(error)) return
            call check(error, sh, sr, atol=1.0e-12_dp * send, message='s history')
            if (allocated(error)) return
            call check(error, uh, ur, atol=1.0e-11_dp * maxval(abs(ur)), message='u history')
            if (allocated(error)) return
        end do
    end subroutine test_coupled_reference

    !> H = 5 m, Vs = 600 m/s: T = 33 ms, the sliding oscillator's period 15 ms (3 samples):
    !> many short slides, each located inside a step.
    subroutine test_coupled_many_slides(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1200
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), sh(n), uh(n), sr(n), ur(n), smax, sfin, tend, send, omega
        a = synthetic(n, dt, 3)
        omega = pi * 600.0_dp / (2.0_dp * 5.0_dp)
        call run_coupled(error, a, dt, omega, 0.1_dp, 0.1_dp, smax, sfin, tend, 'soft', &
                         s_hist=sh, u_hist=uh)
        if (allocated(error)) return
        call reference_coupled(a, dt, g0, omega, 0.1_dp, 0.1_dp, 1000, send, sr, ur)
        call check(error, smax > 1.0e-3_dp, 'slides')
        if (allocated(error)) return
        call check(error, sfin, send, rtol=1.0e-13_dp, message='final s')
        if (allocated(error)) return
        call check(error, sh, sr, atol=1.0e-12_dp * send, message='s history')
    end subroutine test_coupled_many_slides

    !> Vs = 1e5 m/s (omega ~ 1.6e4 rad/s): the coupled displacement tends to the rigid
    !> block's (newmark_rigid, exact) on the record; the difference falls with Vs.
    subroutine test_coupled_rigid_limit(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), smax, sfin, tend, d_prev, d
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: res
        real(dp), parameter :: vss(3) = [1.0e3_dp, 1.0e4_dp, 1.0e5_dp]
        integer :: stat, j
        a = synthetic(n, dt, 4)
        blk%ky = 0.1_dp
        call newmark_rigid(a, dt, blk, NEWMARK_EXACT, g0, res, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'rigid: status')
        if (allocated(error)) return
        d_prev = huge(1.0_dp)
        do j = 1, 3
            call run_coupled(error, a, dt, pi * vss(j) / 20.0_dp, 0.1_dp, 0.1_dp, smax, sfin, &
                             tend, 'stiff')
            if (allocated(error)) return
            d = abs(sfin - res%final_disp)
            call check(error, d < d_prev, 'difference falls with Vs')
            if (allocated(error)) return
            d_prev = d
        end do
        call check(error, sfin, res%final_disp, rtol=1.0e-5_dp, message='Vs = 1e5: rigid')
    end subroutine test_coupled_rigid_limit

    ! ---------------------------------------------------------------- yield tables

    function table_block(d, k) result(b)
        real(dp), intent(in) :: d(:), k(:)
        type(newmark_block_t) :: b
        allocate(b%ky_disp, source=d)
        allocate(b%ky_values, source=k)
    end function table_block

    !> A one-row table is the constant yield, bit for bit (both rules, histories too).
    subroutine test_table_one_row(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), u1(n), u2(n), w1(n), w2(n)
        type(newmark_block_t) :: bc, bt
        type(newmark_result_t) :: r1, r2
        integer :: stat, m
        integer, parameter :: methods(2) = [NEWMARK_EXACT, NEWMARK_SLAMMER]
        a = synthetic(n, dt, 5)
        bc%ky = 0.12_dp
        bt = table_block([0.0_dp], [0.12_dp])
        do m = 1, 2
            call newmark_rigid(a, dt, bc, methods(m), g0, r1, stat, u_hist=u1, w_hist=w1)
            call newmark_rigid(a, dt, bt, methods(m), g0, r2, stat, u_hist=u2, w_hist=w2)
            call check(error, stat, SEISPULSE_SUCCESS, 'status')
            if (allocated(error)) return
            call check(error, r1%final_disp > 0.01_dp .and. identical(u1, u2) &
                       .and. identical(w1, w2) .and. same_bits(r1%final_disp, r2%final_disp) &
                       .and. same_bits(r1%t_end, r2%t_end), 'one row = constant, bitwise')
            if (allocated(error)) return
        end do
    end subroutine test_table_one_row

    !> Rows of equal ky: the table path (kappa = 0, segment ends crossed while sliding)
    !> gives the constant-ky result to rounding.
    subroutine test_table_flat(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), u1(n), u2(n)
        type(newmark_block_t) :: bc, bt
        type(newmark_result_t) :: r1, r2
        integer :: stat, j
        a = synthetic(n, dt, 5)
        bc%ky = 0.12_dp
        bt = table_block([0.0_dp, 0.013_dp, 0.02_dp, 0.3_dp], [0.12_dp, 0.12_dp, 0.12_dp, 0.12_dp])
        call newmark_rigid(a, dt, bc, NEWMARK_EXACT, g0, r1, stat, u_hist=u1)
        call newmark_rigid(a, dt, bt, NEWMARK_EXACT, g0, r2, stat, u_hist=u2)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, r2%final_disp, r1%final_disp, rtol=1.0e-13_dp, message='final')
        if (allocated(error)) return
        call check(error, u2, u1, atol=1.0e-13_dp * r1%final_disp, message='history')
        if (allocated(error)) return
        call check(error, r2%t_end, r1%t_end, rtol=1.0e-12_dp, message='t_end')
        if (allocated(error)) return
        call check(error, size(r2%slides), size(r1%slides), 'slides')
        if (allocated(error)) return
        ! the peak speed inside a step, as the constant rule finds it
        call check(error, r2%max_vel, r1%max_vel, rtol=1.0e-12_dp, message='max_vel')
        if (allocated(error)) return
        do j = 1, size(r1%slides)
            call check(error, r2%slides(j)%w_peak, r1%slides(j)%w_peak, rtol=1.0e-12_dp, &
                       message='w_peak')
            if (allocated(error)) return
            call check(error, r2%slides(j)%t_peak, r1%slides(j)%t_peak, atol=1.0e-9_dp, &
                       message='t_peak')
            if (allocated(error)) return
        end do
    end subroutine test_table_flat

    !> A tiny last yield (1e-9 g): the run-out after the record is long; the table gives the
    !> constant rule's value (the same closed form w^2/(2 ky)); a table softening to 1e-9 g
    !> gives a value.
    subroutine test_table_long_runout(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1000
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n)
        type(newmark_block_t) :: bc, bt
        type(newmark_result_t) :: r1, r2
        integer :: stat
        a = synthetic(n, dt, 5)
        a(n - 100:n) = 0.4_dp
        bc%ky = 1.0e-9_dp
        bt = table_block([0.0_dp, 1.0e3_dp], [1.0e-9_dp, 1.0e-9_dp])
        call newmark_rigid(a, dt, bc, NEWMARK_EXACT, g0, r1, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'constant: status')
        if (allocated(error)) return
        call newmark_rigid(a, dt, bt, NEWMARK_EXACT, g0, r2, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'table: status')
        if (allocated(error)) return
        call check(error, r2%final_disp, r1%final_disp, rtol=1.0e-9_dp, message='final')
        if (allocated(error)) return
        call check(error, r2%t_end, r1%t_end, rtol=1.0e-9_dp, message='t_end')
        if (allocated(error)) return
        bt = table_block([0.0_dp, 0.01_dp], [0.3_dp, 1.0e-9_dp])
        call newmark_rigid(a, dt, bt, NEWMARK_EXACT, g0, r2, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'softening to 1e-9: status')
        call check(error, r2%final_disp > 0.01_dp .and. ieee_is_finite(r2%final_disp), &
                   'softening to 1e-9: slides past the table')
    end subroutine test_table_long_runout

    !> ky falls from 0.15 to 0.06 over 2 cm then rises to 0.11 at 10 cm: exact = RK4 with
    !> 400 sub-steps per sample, stops and onsets by bisection (g = 9.80665).
    subroutine test_table_reference(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp), parameter :: kd(3) = [0.0_dp, 0.02_dp, 0.1_dp]
        real(dp), parameter :: kv(3) = [0.15_dp, 0.06_dp, 0.11_dp]
        real(dp) :: a(n), u1(n), ur(n), uend
        type(newmark_block_t) :: bt
        type(newmark_result_t) :: r1
        integer :: stat
        a = synthetic(n, dt, 6)
        bt = table_block(kd, kv)
        call newmark_rigid(a, dt, bt, NEWMARK_EXACT, g0, r1, stat, u_hist=u1)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call reference_table(a, dt, kd, kv, 400, ur, uend)
        call check(error, r1%final_disp > 0.1_dp, 'slides past the table')
        if (allocated(error)) return
        call check(error, r1%final_disp, uend, rtol=1.0e-11_dp, message='final')
        if (allocated(error)) return
        call check(error, u1, ur, atol=1.0e-11_dp * uend, message='history')
    end subroutine test_table_reference

    !> Rigid block with ky(u) from the table: RK4 on m sub-steps, events by bisection.
    subroutine reference_table(accel, dt, kd, kv, m, u_hist, u_end)
        real(dp), intent(in) :: accel(:), dt, kd(:), kv(:)
        integer, intent(in) :: m
        real(dp), intent(out) :: u_hist(:), u_end
        real(dp) :: y(2), y1(2), hs, t, rest, tl, th, tm, ym(2)
        integer :: i, j, k, it, b, n
        logical :: slide
        n = size(accel)
        hs = dt / m
        y = 0.0_dp
        slide = accel(1) > kyu(0.0_dp)
        u_hist(1) = 0.0_dp
        i = 0
        do k = 1, 10000000
            i = i + 1
            if (i > n - 1 .and. .not. slide) exit
            do j = 0, m - 1
                t = real(i - 1, dp) * dt + j * hs
                rest = hs
                do it = 1, 4
                    y1 = rk4(y, t, rest)
                    if ((slide .and. y1(2) < 0.0_dp) .or. &
                        (.not. slide .and. acc_at(t + rest) > kyu(y(1)))) then
                        tl = 0.0_dp
                        th = rest
                        do b = 1, 200
                            tm = 0.5_dp * (tl + th)
                            if (.not. (tm > tl .and. tm < th)) exit
                            ym = rk4(y, t, tm)
                            if ((slide .and. ym(2) < 0.0_dp) .or. &
                                (.not. slide .and. acc_at(t + tm) > kyu(y(1)))) then
                                th = tm
                            else
                                tl = tm
                            end if
                        end do
                        y = rk4(y, t, th)
                        if (slide) y(2) = 0.0_dp
                        slide = .not. slide
                        t = t + th
                        rest = rest - th
                    else
                        y = y1
                        exit
                    end if
                end do
            end do
            if (i <= n - 1) u_hist(i + 1) = y(1)
        end do
        u_end = y(1)
    contains
        real(dp) function kyu(u)
            real(dp), intent(in) :: u
            integer :: l
            kyu = kv(size(kv))
            do l = 1, size(kd) - 1
                if (u < kd(l + 1)) then
                    kyu = kv(l) + (kv(l + 1) - kv(l)) * (u - kd(l)) / (kd(l + 1) - kd(l))
                    return
                end if
            end do
        end function kyu
        real(dp) function acc_at(tt)
            real(dp), intent(in) :: tt
            acc_at = record_at(accel, dt, tt)
        end function acc_at
        function rhs(yy, tt) result(f)
            real(dp), intent(in) :: yy(2), tt
            real(dp) :: f(2)
            if (slide) then
                f = [yy(2), g0 * (acc_at(tt) - kyu(yy(1)))]
            else
                f = 0.0_dp
            end if
        end function rhs
        function rk4(yy, tt, hh) result(yn)
            real(dp), intent(in) :: yy(2), tt, hh
            real(dp) :: yn(2), k1(2), k2(2), k3(2), k4(2)
            k1 = rhs(yy, tt)
            k2 = rhs(yy + 0.5_dp * hh * k1, tt + 0.5_dp * hh)
            k3 = rhs(yy + 0.5_dp * hh * k2, tt + 0.5_dp * hh)
            k4 = rhs(yy + hh * k3, tt + hh)
            yn = yy + hh / 6.0_dp * (k1 + 2.0_dp * k2 + 2.0_dp * k3 + k4)
        end function rk4
    end subroutine reference_table

    !> SLAMMER RigidBlock's loop with a table (one way, cm), written out here.
    subroutine test_table_slammer(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp), parameter :: kd(3) = [0.0_dp, 0.02_dp, 0.1_dp]
        real(dp), parameter :: kv(3) = [0.15_dp, 0.06_dp, 0.11_dp]
        real(dp) :: a(n), u1(n), ue(n), q, r, s, u, v, y, tt, nn, aa, gcm, prop, dcm(3)
        type(newmark_block_t) :: bt
        type(newmark_result_t) :: r1
        integer :: stat, i, pos
        a = synthetic(n, dt, 6)
        bt = table_block(kd, kv)
        call newmark_rigid(a, dt, bt, NEWMARK_SLAMMER, g0, r1, stat, u_hist=u1)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        gcm = 100.0_dp * g0
        dcm = 100.0_dp * kd
        tt = kv(1) * gcm
        q = 0.0_dp
        r = 0.0_dp
        s = 0.0_dp
        u = 0.0_dp
        v = 0.0_dp
        pos = 1
        do i = 1, n
            aa = a(i) * gcm
            if (abs(v) < 1.0e-15_dp) then
                if (abs(aa) > tt) then
                    nn = sign(1.0_dp, aa)
                else
                    nn = aa / tt
                end if
            else
                nn = sign(1.0_dp, v)
            end if
            y = aa - nn * tt
            v = r + dt / 2.0_dp * (y + s)
            if (v <= 0.0_dp) then
                v = 0.0_dp
                y = 0.0_dp
            end if
            u = q + dt / 2.0_dp * (v + r)
            q = u
            r = v
            s = y
            ue(i) = u / 100.0_dp
            if (pos == 3) cycle
            do while (u > dcm(pos + 1))
                pos = pos + 1
                if (pos == 3) exit
            end do
            if (pos == 3) then
                tt = gcm * kv(3)
            else
                prop = (u - dcm(pos)) / (dcm(pos + 1) - dcm(pos))
                tt = gcm * (kv(pos) - (kv(pos) - kv(pos + 1)) * prop)
            end if
        end do
        call check(error, ue(n) > 0.1_dp, 'slides past the table')
        if (allocated(error)) return
        call check(error, u1, ue, atol=1.0e-15_dp * ue(n), message='RigidBlock rule')
    end subroutine test_table_slammer

    !> A one-row table is the constant yield, bit for bit.
    subroutine test_coupled_table_one_row(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), s1(n), s2(n), v1(n), v2(n), u1(n), u2(n), smax, sfin, tend, sfin2, om
        a = synthetic(n, dt, 2)
        om = pi * 300.0_dp / 40.0_dp
        call run_coupled(error, a, dt, om, 0.2_dp, 0.12_dp, smax, sfin, tend, 'constant', &
                         s_hist=s1, u_hist=u1, v_hist=v1)
        if (allocated(error)) return
        call run_coupled(error, a, dt, om, 0.2_dp, 7.0_dp, smax, sfin2, tend, 'one row', &
                         s_hist=s2, u_hist=u2, v_hist=v2, kd=[0.0_dp], kv=[0.12_dp])
        if (allocated(error)) return
        call check(error, sfin > 0.01_dp .and. identical(s1, s2) .and. identical(v1, v2) &
                   .and. identical(u1, u2) .and. same_bits(sfin, sfin2), 'bitwise')
    end subroutine test_coupled_table_one_row

    !> Equal rows: the integrator path (DOP853, segment ends crossed) = closed form.
    subroutine test_coupled_table_flat(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), s1(n), s2(n), smax, sfin, tend, sfin2, om
        a = synthetic(n, dt, 2)
        om = pi * 300.0_dp / 40.0_dp
        call run_coupled(error, a, dt, om, 0.2_dp, 0.12_dp, smax, sfin, tend, 'constant', &
                         s_hist=s1)
        if (allocated(error)) return
        call run_coupled(error, a, dt, om, 0.2_dp, 0.12_dp, smax, sfin2, tend, 'flat', &
                         s_hist=s2, kd=[0.0_dp, 0.003_dp, 0.02_dp], kv=[0.12_dp, 0.12_dp, 0.12_dp])
        if (allocated(error)) return
        call check(error, sfin2, sfin, rtol=1.0e-11_dp, message='final')
        if (allocated(error)) return
        call check(error, s2, s1, atol=1.0e-11_dp * sfin, message='history')
    end subroutine test_coupled_table_flat

    !> ky falls from 0.15 to 0.07 over 1 cm then rises to 0.1 at 5 cm, H = 20 m,
    !> Vs = 300 m/s: exact (DOP853 for the slides) = RK4 with 400 sub-steps.
    subroutine test_coupled_table_reference(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp), parameter :: kd(3) = [0.0_dp, 0.01_dp, 0.05_dp]
        real(dp), parameter :: kv(3) = [0.15_dp, 0.07_dp, 0.1_dp]
        real(dp) :: a(n), sh(n), uh(n), sr(n), ur(n), smax, sfin, tend, send, om
        a = synthetic(n, dt, 2)
        om = pi * 300.0_dp / 40.0_dp
        call run_coupled(error, a, dt, om, 0.2_dp, 1.0_dp, smax, sfin, tend, 'table', &
                         s_hist=sh, u_hist=uh, kd=kd, kv=kv)
        if (allocated(error)) return
        call reference_coupled(a, dt, g0, om, 0.2_dp, 1.0_dp, 400, send, sr, ur, kd, kv)
        call check(error, sfin > 0.06_dp, 'slides past the table')
        if (allocated(error)) return
        call check(error, sfin, send, rtol=1.0e-10_dp, message='final s')
        if (allocated(error)) return
        call check(error, sh, sr, atol=1.0e-10_dp * send, message='s history')
    end subroutine test_coupled_table_reference

    !> The decoupled analysis (the rigid exact rule on the HEA of the exact modal
    !> response, doc/flexible.md (F.36)) tends to the rigid block on the record itself.
    subroutine test_decoupled_rigid_limit(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), u(n), hea(n), d_prev, d
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: res, rd
        real(dp), parameter :: vss(3) = [1.0e3_dp, 1.0e4_dp, 1.0e5_dp]
        integer :: stat, j
        a = synthetic(n, dt, 4)
        blk%ky = 0.1_dp
        call newmark_rigid(a, dt, blk, NEWMARK_EXACT, g0, res, stat)
        d_prev = huge(1.0_dp)
        do j = 1, 3
            call modal_response_exact(a, dt, g0, pi * vss(j) / 20.0_dp, 0.1_dp, u, hea, stat)
            call newmark_rigid(hea, dt, blk, NEWMARK_EXACT, g0, rd, stat)
            call check(error, stat, SEISPULSE_SUCCESS, 'status')
            if (allocated(error)) return
            d = abs(rd%final_disp - res%final_disp)
            call check(error, d < d_prev, 'difference falls with Vs')
            if (allocated(error)) return
            d_prev = d
        end do
        call check(error, rd%final_disp, res%final_disp, rtol=1.0e-5_dp, message='Vs = 1e5')
    end subroutine test_decoupled_rigid_limit

    !> One lobe of the exponential pulse (A = 1, t_d = 1 s, g = 1) sampled at t_d/256 on a
    !> mass of omega = 2e4 rad/s: coupled and decoupled slips equal the rigid block's
    !> (1e-6) and the closed form of the half cycle (seispulse_sliding_closed) to the
    !> O(dt^2) of the sampling.
    subroutine test_pulse_closed_form(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: ns = 256
        real(dp), parameter :: betas(2) = [-pi, 0.4_dp], eta = 0.3_dp, om = 2.0e4_dp
        real(dp) :: tau(ns + 1), a(ns + 1), v(ns + 1), d(ns + 1), u(ns + 1), hea(ns + 1)
        real(dp) :: smax, sfin, tend
        type(half_cycle_t) :: hc
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: res, rd
        integer :: i, j, stat
        character(len=200) :: msg
        tau = [(real(i - 1, dp) / ns, i = 1, ns + 1)]
        blk%ky = eta
        do j = 1, 2
            call half_cycle(eta, betas(j), 1.0_dp, hc, stat)
            call exp_pulse(tau, [betas(j)], .false., a, v, d, stat)
            call newmark_rigid(a, 1.0_dp / ns, blk, NEWMARK_EXACT, 1.0_dp, res, stat)
            call coupled_exact(a, 1.0_dp / ns, 1.0_dp, om, 0.1_dp, eta, smax, sfin, tend, stat, &
                               msg)
            call check(error, stat, SEISPULSE_SUCCESS, 'coupled status')
            if (allocated(error)) return
            call modal_response_exact(a, 1.0_dp / ns, 1.0_dp, om, 0.1_dp, u, hea, stat)
            call newmark_rigid(hea, 1.0_dp / ns, blk, NEWMARK_EXACT, 1.0_dp, rd, stat)
            call check(error, sfin, res%final_disp, rtol=1.0e-6_dp, message='coupled = rigid')
            if (allocated(error)) return
            call check(error, rd%final_disp, res%final_disp, rtol=1.0e-6_dp, &
                       message='decoupled = rigid')
            if (allocated(error)) return
            call check(error, sfin, hc%um, rtol=3.0e-4_dp, message='coupled = closed form')
            if (allocated(error)) return
            call check(error, rd%final_disp, hc%um, rtol=3.0e-4_dp, &
                       message='decoupled = closed form')
            if (allocated(error)) return
        end do
    end subroutine test_pulse_closed_form

    !> The exact coupled solution depends only on the piecewise-linear record: sampling it
    !> 8 times finer (linear interpolation) gives the same slip (dt = 0.02 s, H = 5 m,
    !> Vs = 600 m/s: the sliding oscillator's period, 15 ms, is shorter than a step).
    subroutine test_coupled_upsampling(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 600, m = 8
        real(dp), parameter :: dt = 0.02_dp
        real(dp) :: a(n), b((n - 1) * m + 1), sh(n), sb((n - 1) * m + 1), smax, s1, s2, tend, om
        integer :: i, j
        a = synthetic(n, dt, 7)
        do i = 1, n - 1
            do j = 0, m - 1
                b((i - 1) * m + j + 1) = a(i) + (a(i + 1) - a(i)) * (real(j, dp) / m)
            end do
        end do
        b(size(b)) = a(n)
        om = pi * 600.0_dp / 10.0_dp
        call run_coupled(error, a, dt, om, 0.25_dp, 0.1_dp, smax, s1, tend, 'samples', s_hist=sh)
        if (allocated(error)) return
        call run_coupled(error, b, dt / m, om, 0.25_dp, 0.1_dp, smax, s2, tend, 'upsampled', &
                         s_hist=sb)
        if (allocated(error)) return
        call check(error, s1 > 0.01_dp, 'slides')
        if (allocated(error)) return
        call check(error, s2, s1, rtol=1.0e-12_dp, message='final s')
        if (allocated(error)) return
        call check(error, sb(1::m), sh, atol=1.0e-12_dp * s1, message='s at the samples')
    end subroutine test_coupled_upsampling

    !> The dispatch of seispulse_flexible (linear soil): the decoupled slip is the rigid
    !> exact rule on the HEA of modal_response_exact for the final omega, xi (F.36), bit for
    !> bit, with a constant yield, two ways and a yield table.
    subroutine test_dispatch_decoupled(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 800, np = 4000
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n + np), u(n + np), hea(n + np), s1(n), s2(n + np), om
        real(dp) :: sfin, tend
        type(flexible_mass_t) :: m
        type(flexible_result_t) :: r
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: rr
        integer :: stat, k
        character(len=200) :: msg
        ! the record stops at 4 s in strong shaking, its last sample 0; the reference pads
        ! it with zeros (F.48)
        a = 0.0_dp
        a(1:n) = synthetic(n, dt, 8)
        a(n) = 0.0_dp
        m = flexible_mass_t(height=20.0_dp, vs=300.0_dp, vs_base=900.0_dp, damping=0.05_dp)
        do k = 1, 3
            msg = ''
            select case (k)
            case (1)
                call flexible_decoupled(a(1:n), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, msg, s_hist=s1)
                blk = newmark_block_t()
                blk%ky = 0.1_dp
            case (2)
                call flexible_decoupled(a(1:n), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, msg, &
                                        mode=2, s_hist=s1)
                blk = newmark_block_t(mode=2, ky=0.1_dp)
            case default
                call flexible_decoupled(a(1:n), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, msg, &
                                        ky_disp=[0.0_dp, 0.02_dp], ky_values=[0.12_dp, 0.07_dp], &
                                        s_hist=s1)
                blk = newmark_block_t()
                allocate(blk%ky_disp, source=[0.0_dp, 0.02_dp])
                allocate(blk%ky_values, source=[0.12_dp, 0.07_dp])
            end select
            call check(error, stat, SEISPULSE_SUCCESS, 'decoupled: '//trim(msg))
            if (allocated(error)) return
            om = pi * r%vs_final / (2.0_dp * m%height)
            call modal_response_exact(a, dt, g0, om, r%damping_final, u, hea, stat)
            call newmark_rigid(hea, dt, blk, NEWMARK_EXACT, g0, rr, stat, u_hist=s2)
            call check(error, r%max_disp > 0.01_dp .and. identical(s1, s2(1:n)) &
                       .and. same_bits(r%final_disp, rr%final_disp) &
                       .and. same_bits(r%t_end, rr%t_end), 'bitwise')
            if (allocated(error)) return
            sfin = r%final_disp
            tend = r%t_end
            ! zero-padding the record changes nothing (the same final s and t_end)
            select case (k)
            case (1)
                call flexible_decoupled(a(1:n + 2000), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, &
                                        msg)
            case (2)
                call flexible_decoupled(a(1:n + 2000), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, &
                                        msg, mode=2)
            case default
                call flexible_decoupled(a(1:n + 2000), dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, &
                                        msg, ky_disp=[0.0_dp, 0.02_dp], &
                                        ky_values=[0.12_dp, 0.07_dp])
            end select
            call check(error, stat, SEISPULSE_SUCCESS, 'padded: '//trim(msg))
            if (allocated(error)) return
            call check(error, r%final_disp, sfin, rtol=1.0e-12_dp, message='padded: final s')
            if (allocated(error)) return
            call check(error, r%t_end, tend, rtol=1.0e-12_dp, message='padded: t_end')
            if (allocated(error)) return
        end do
    end subroutine test_dispatch_decoupled

    !> The dispatch of seispulse_flexible: flexible_coupled(FLEX_EXACT) is coupled_exact for
    !> the final omega, xi, bit for bit (constant yield and table).
    subroutine test_dispatch_coupled(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1600
        real(dp), parameter :: dt = 0.005_dp
        real(dp) :: a(n), s1(n), s2(n), om, smax, sfin, tend
        type(flexible_mass_t) :: m
        type(flexible_result_t) :: r
        integer :: stat, k
        character(len=200) :: msg
        a = synthetic(n, dt, 8)
        m = flexible_mass_t(height=20.0_dp, vs=300.0_dp, vs_base=900.0_dp, damping=0.05_dp)
        do k = 1, 2
            msg = ''
            if (k == 1) then
                call flexible_coupled(a, dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, msg, s_hist=s1)
            else
                call flexible_coupled(a, dt, 0.1_dp, m, FLEX_EXACT, g0, r, stat, msg, &
                                      ky_disp=[0.0_dp, 0.02_dp], ky_values=[0.12_dp, 0.07_dp], &
                                      s_hist=s1)
            end if
            call check(error, stat, SEISPULSE_SUCCESS, 'coupled: '//trim(msg))
            if (allocated(error)) return
            om = pi * r%vs_final / (2.0_dp * m%height)
            if (k == 1) then
                call coupled_exact(a, dt, g0, om, r%damping_final, 0.1_dp, smax, sfin, tend, stat, &
                                   s_hist=s2)
            else
                call coupled_exact(a, dt, g0, om, r%damping_final, 0.1_dp, smax, sfin, tend, stat, &
                                   ky_disp=[0.0_dp, 0.02_dp], ky_values=[0.12_dp, 0.07_dp], &
                                   s_hist=s2)
            end if
            call check(error, r%max_disp > 0.01_dp .and. identical(s1, s2) &
                       .and. same_bits(r%final_disp, sfin), 'bitwise')
            if (allocated(error)) return
        end do
    end subroutine test_dispatch_coupled

    subroutine dip_taylor(self, x, f)
        class(dip_t), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp), intent(out) :: f(0:2)
        real(dp) :: p, q
        p = x - 0.3_dp
        q = x - 0.31_dp
        f(0) = p**2 * q**2 + self%lift
        f(1) = 2.0_dp * p * q**2 + 2.0_dp * p**2 * q
        f(2) = 2.0_dp * q**2 + 8.0_dp * p * q + 2.0_dp * p**2
    end subroutine dip_taylor

    !> f = (x - 0.3)^2 (x - 0.31)^2 + lift on (0, 1]: lift < 0 gives two zeros close to
    !> 0.3 and two near 0.31 (the first is found, not a later one); lift > 0 none.
    subroutine test_first_zero(error)
        type(test_error), allocatable, intent(out) :: error
        type(dip_t) :: f
        real(dp) :: fa(0:2), fb(0:2), x, m3, lift, xe
        logical :: found
        integer :: stat
        m3 = 24.0_dp * 1.0_dp   ! |f'''| = |24 x - 12 (0.61)| <= 24 on [0, 1]
        lift = -1.0e-10_dp
        f%lift = lift
        call f%taylor(0.0_dp, fa)
        call f%taylor(1.0_dp, fb)
        call first_zero(f, 1.0_dp, fa, fb, m3, found, x, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, found, 'found')
        if (allocated(error)) return
        ! first zero: p^2 q^2 = 1e-10, p q = -1e-5 with p > 0 > q... the smallest root of
        ! x^2 - 0.61 x + 0.093 + 1e-5 = 0 is wrong-sided: p q = +-1e-5; the first crossing is
        ! where p q = 1e-5 with p < 0: x = (0.61 - sqrt(0.61^2 - 4 (0.093 - 1e-5)))/2
        xe = 0.5_dp * (0.61_dp - sqrt(0.61_dp**2 - 4.0_dp * (0.093_dp - 1.0e-5_dp)))
        call check(error, x, xe, rtol=1.0e-12_dp, message='first of four zeros')
        if (allocated(error)) return
        f%lift = 1.0e-12_dp
        call f%taylor(0.0_dp, fa)
        call f%taylor(1.0_dp, fb)
        call first_zero(f, 1.0_dp, fa, fb, m3, found, x, stat)
        call check(error, .not. found, 'no zero above the axis')
    end subroutine test_first_zero

    !> The record stops at 4 s in strong shaking (its last sample 0) with the beam ringing
    !> (H = 100 m, Vs = 600 m/s): with ky = 0.05 the free vibration starts a new slide after
    !> the record. The same record with 2000 zeros appended gives the same final s and t_end
    !> (F.48); the RK4 reference with the same end rule gives the same final s.
    subroutine test_coupled_zero_padding(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 400, np = 2000
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n + np), smax, sfin, tend, sfin2, tend2, omega, send, s05
        real(dp) :: sr(n), ur(n)
        real(dp), parameter :: kys(2) = [0.05_dp, 0.1_dp]
        integer :: j
        a = 0.0_dp
        a(1:n) = 2.0_dp * synthetic(n, dt, 5)
        a(n) = 0.0_dp
        omega = pi * 600.0_dp / (2.0_dp * 100.0_dp)
        do j = 1, 2
            call run_coupled(error, a(1:n), dt, omega, 0.05_dp, kys(j), smax, sfin, tend, &
                             'record')
            if (allocated(error)) return
            call run_coupled(error, a, dt, omega, 0.05_dp, kys(j), smax, sfin2, tend2, 'padded')
            if (allocated(error)) return
            call check(error, sfin > 1.0e-3_dp, 'slides')
            if (allocated(error)) return
            call check(error, sfin2, sfin, rtol=1.0e-12_dp, message='final s, padded, ky = ' &
                       //trim(num(kys(j))))
            if (allocated(error)) return
            call check(error, tend2, tend, rtol=1.0e-12_dp, message='t_end, padded')
            if (allocated(error)) return
            if (j == 1) s05 = sfin
        end do
        ! the RK4 reference with the same end rule (ky = 0.05: a slide after the record)
        call reference_coupled(a(1:n), dt, g0, omega, 0.05_dp, 0.05_dp, 200, send, sr, ur)
        call check(error, s05, send, rtol=1.0e-11_dp, message='final s = RK4')
    end subroutine test_coupled_zero_padding

    !> Stiff masses: omega = 1.6e6 and 1.6e7 rad/s (Vs = 1e5 m/s, H = 0.1 and 0.01 m) and
    !> H = 1e-5 m (omega = 1.6e10 rad/s) on a record with dt = 0.01 s: a result (no
    !> error), close to the rigid block's (newmark_rigid, exact).
    subroutine test_coupled_stiff(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 800
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n), smax, sfin, tend
        real(dp), parameter :: hs(3) = [0.1_dp, 0.01_dp, 1.0e-5_dp]
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: res
        integer :: stat, j
        a = 2.0_dp * synthetic(n, dt, 6)
        blk%ky = 0.1_dp
        call newmark_rigid(a, dt, blk, NEWMARK_EXACT, g0, res, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'rigid: status')
        if (allocated(error)) return
        do j = 1, 3
            call run_coupled(error, a, dt, pi * 1.0e5_dp / (2.0_dp * hs(j)), 0.25_dp, 0.1_dp, &
                             smax, sfin, tend, 'stiff, H = '//trim(num(hs(j))))
            if (allocated(error)) return
            call check(error, sfin, res%final_disp, rtol=1.0e-3_dp, message='rigid limit, H = ' &
                       //trim(num(hs(j))))
            if (allocated(error)) return
        end do
    end subroutine test_coupled_stiff

    !> A negative damping that overflows the modal response is a status, not Inf.
    subroutine test_modal_overflow(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 20000
        real(dp) :: a(n), u(n), hea(n)
        integer :: stat
        character(len=200) :: msg
        a = synthetic(n, 0.01_dp, 1)
        msg = ''
        call modal_response_exact(a, 0.01_dp, g0, 600.0_dp, -0.9_dp, u, hea, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'overflow: status')
        if (allocated(error)) return
        call check(error, index(msg, 'xi') > 0, 'message names xi: '//trim(msg))
    end subroutine test_modal_overflow

    !> An infinite bound on f''' never proves a zero absent: first_zero returns a status.
    subroutine test_first_zero_inf(error)
        type(test_error), allocatable, intent(out) :: error
        type(dip_t) :: f
        real(dp) :: fa(0:2), fb(0:2), x
        logical :: found
        integer :: stat
        f%lift = -1.0e-10_dp
        call f%taylor(0.0_dp, fa)
        call f%taylor(1.0_dp, fb)
        call first_zero(f, 1.0_dp, fa, fb, ieee_value(1.0_dp, ieee_positive_inf), found, x, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'status')
    end subroutine test_first_zero_inf

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(10), u(10), hea(10), smax, sfin, tend
        integer :: stat
        character(len=200) :: msg
        a = 0.1_dp
        msg = ''
        call modal_response_exact(a, 0.01_dp, g0, 10.0_dp, -1.0_dp, u, hea, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'xi = -1')
        if (allocated(error)) return
        call check(error, index(msg, 'xi') > 0, 'message names xi: '//trim(msg))
        if (allocated(error)) return
        call coupled_exact(a, 0.01_dp, g0, -1.0_dp, 0.1_dp, 0.1_dp, smax, sfin, tend, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'omega < 0')
        if (allocated(error)) return
        call coupled_exact(a, 0.01_dp, g0, 10.0_dp, 0.1_dp, 0.0_dp, smax, sfin, tend, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'ky = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'ky') > 0, 'message names ky: '//trim(msg))
    end subroutine test_bad_input

    !> The arrays have the same bits.
    pure logical function identical(a, b)
        real(dp), intent(in) :: a(:), b(:)
        integer :: i
        identical = size(a) == size(b)
        do i = 1, min(size(a), size(b))
            identical = identical .and. same_bits(a(i), b(i))
        end do
    end function identical

    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=24) :: s
        write (s, '(g0.4)') x
    end function num

end module test_flexible_exact
