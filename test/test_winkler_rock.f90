!> Rocking on tensionless Winkler springs and dashpots (doc/winkler.md section "Dynamics"):
!> vertical motion against the closed form of the linear spring-dashpot, a drop (free fall,
!> touch-down at sqrt(2 d/g)), the lift-off and touch-down of a rebound from the closed form,
!> the quasi-static check against the thesis's closed-form pushover (written here), the
!> energy balance over a history with impacts (and the input work by quadrature here), the
!> energy criterion of safety, the trend to the rigid-ground threshold as k grows, the exact
!> Jacobian against central differences at every contact structure, and bad input. Every
!> expected value is computed here independently.
module test_winkler_rock
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf, &
                                             ieee_is_nan, ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props, &
                                  overturning_threshold, MAP_AXES_DIMENSIONAL, &
                                  MAP_AXES_DIMENSIONLESS, body_overturning_map
    use seispulse_pulses, only: pulse_t, PULSE_SINE_CYCLE, PULSE_MP, PULSE_RICKER
    use seispulse_winkler, only: K_CONSTANT, K_VARYING, WP_FORCE, WP_NCOL, winkler_pushover_t, &
                                 winkler_pushover, block_winkler_pushover
    use seispulse_winkler_rock, only: winkler_model_t, winkler_run_t, winkler_model, &
                                      winkler_rock, winkler_overturning_map, winkler_rhs_jacobian, &
                                      winkler_barrier, winkler_outcome_name, winkler_output_name, &
                                      DAMP_ROCKING, DAMP_VERTICAL, WR_NOUT, WR_OUT_V, &
                                      WR_OUT_THETA, WR_OUT_V_RATE, WR_OUT_THETA_RATE, &
                                      WR_OUT_NORMAL, WR_OUT_ACCEL, WR_OUT_ENERGY, WR_OUT_WORK, &
                                      WR_OUT_DISSIPATED, WR_OUT_WIDTH, WR_RUN_SAFE, &
                                      WR_RUN_OVERTURN_NO_IMPACT, WR_RUN_OVERTURN_IMPACTS, &
                                      WR_RUN_TIME_LIMIT
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_winkler_rock

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g = 9.81_dp

contains

    subroutine collect_winkler_rock(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('vertical motion: linear spring-dashpot closed form', &
                              test_vertical), &
                 new_unittest('drop: free fall, touch-down at sqrt(2 d/g) to 1e-9 s', test_drop), &
                 new_unittest('rebound: lift-off and touch-down times from the closed form', &
                              test_rebound), &
                 new_unittest('quasi-static: one sine cycle of T = 19 s vs the closed-form' &
                              //' pushover', test_quasi_static), &
                 new_unittest('quasi-static: block (closed form) and varying k vs the pushover' &
                              //' of seispulse_winkler', test_quasi_static_more), &
                 new_unittest('energy balance over a history with impacts', test_energy), &
                 new_unittest('record in g: the sampled pulse gives the pulse run', test_record), &
                 new_unittest('energy criterion: below the barrier safe, above it overturns', &
                              test_energy_criterion), &
                 new_unittest('exact Jacobian vs central differences, every contact structure', &
                              test_jacobian), &
                 new_unittest('k -> infinity: one-sine threshold tends to the rigid one', &
                              test_rigid_limit), &
                 new_unittest('bad input', test_bad_input), &
                 new_unittest('varying k map: a standing cell is safe; theta_max a turning point', &
                              test_varying_map), &
                 new_unittest('kern-level rocking is no impact: Ricker class as rigid for large k', &
                              test_kern_rocking), &
                 new_unittest('outcome decided at the end of the excitation; free run', &
                              test_end_of_excitation)]
    end subroutine collect_winkler_rock

    !> A solid cylinder r = 1 m, h = 3 m of concrete (2500 kg/m^3) and its model.
    subroutine cylinder_model(k, model, stat, xi, damping_ref, c, k_method)
        real(dp), intent(in) :: k
        type(winkler_model_t), intent(out) :: model
        integer, intent(out) :: stat
        real(dp), intent(in), optional :: xi, c
        integer, intent(in), optional :: damping_ref, k_method
        type(rocking_body_t) :: body
        call cylinder_props(1.0_dp, 3.0_dp, 2500.0_dp * pi * 6.0_dp, g, body, stat)
        if (stat /= 0) return
        call winkler_model(body, k, model, stat, xi=xi, damping_ref=damping_ref, c=c, &
                           k_method=k_method)
    end subroutine cylinder_model

    !> Free vertical motion about the static settlement: m u'' + c A u' + k A u = 0,
    !> u = v - W/(k A), underdamped closed form; theta stays 0, N = k A v + c A v'.
    subroutine test_vertical(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        real(dp) :: tg(41), hist(WR_NOUT, 41), m, a, kk, cc, wn, z, wd, u0, u, ud, e
        integer :: stat, i
        call cylinder_model(1.0e9_dp, model, stat, xi=0.05_dp, damping_ref=DAMP_VERTICAL)
        call check(error, stat == 0, 'model')
        if (allocated(error)) return
        m = model%body%mass
        a = pi
        kk = model%k * a
        cc = model%c * a
        call check(error, cc, 2.0_dp * 0.05_dp * sqrt(kk * m), rtol=1.0e-14_dp, &
                   message='c from xi (vertical)')
        if (allocated(error)) return
        wn = sqrt(kk / m)
        z = cc / (2.0_dp * sqrt(kk * m))
        wd = wn * sqrt(1.0_dp - z * z)
        u0 = 0.3_dp * model%v_static
        do i = 1, 41
            tg(i) = 0.005_dp * (i - 1)
        end do
        call winkler_rock(model, tg, hist, run, stat, v0=model%v_static + u0, rtol=1.0e-11_dp)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        do i = 1, 41
            e = exp(-z * wn * tg(i))
            u = u0 * e * (cos(wd * tg(i)) + z * wn / wd * sin(wd * tg(i)))
            ud = -u0 * e * (wn * wn / wd) * sin(wd * tg(i))
            call check(error, hist(WR_OUT_V, i), model%v_static + u, &
                       atol=2.0e-8_dp * model%v_static, rtol=0.0_dp, message="v(t)")
            if (allocated(error)) return
            call check(error, hist(WR_OUT_V_RATE, i), ud, atol=2.0e-8_dp * model%v_static * wn, &
                       rtol=0.0_dp, message="v'(t)")
            if (allocated(error)) return
            call check(error, abs(hist(WR_OUT_THETA, i)) <= 0.0_dp, 'theta stays 0')
            if (allocated(error)) return
            call check(error, hist(WR_OUT_NORMAL, i), kk * hist(WR_OUT_V, i) &
                       + cc * hist(WR_OUT_V_RATE, i), rtol=1.0e-12_dp, message='N = k A v + c A v''')
            if (allocated(error)) return
            call check(error, hist(WR_OUT_WIDTH, i), 2.0_dp, rtol=0.0_dp, message='full contact')
            if (allocated(error)) return
        end do
        call check(error, run%outcome == WR_RUN_TIME_LIMIT .or. run%outcome == WR_RUN_SAFE, &
                   'standing')
        if (allocated(error)) return
        call check(error, ieee_is_nan(run%t_uplift) .and. run%n_impacts == 0, 'no uplift')
    end subroutine test_vertical

    !> From d above the ground at rest: free fall, both edges touch at t = sqrt(2 d/g).
    subroutine test_drop(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        real(dp) :: tg(3), hist(WR_NOUT, 3), d
        integer :: stat
        d = 0.01_dp
        call cylinder_model(1.0e9_dp, model, stat, xi=0.05_dp, damping_ref=DAMP_VERTICAL)
        tg = [0.02_dp, 0.04_dp, 0.3_dp]
        call winkler_rock(model, tg, hist, run, stat, v0=-d, rtol=1.0e-10_dp)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, run%t_lift_off, 0.0_dp, rtol=0.0_dp, message='no contact at the start')
        if (allocated(error)) return
        call check(error, run%t_touch_down, sqrt(2.0_dp * d / g), atol=1.0e-9_dp, rtol=0.0_dp, &
                   message='touch-down time')
        if (allocated(error)) return
        call check(error, hist(WR_OUT_V, 1), -d + 0.5_dp * g * tg(1)**2, rtol=1.0e-13_dp, &
                   message='free fall')
        if (allocated(error)) return
        call check(error, abs(hist(WR_OUT_NORMAL, 1)) <= 0.0_dp .and. &
                          abs(hist(WR_OUT_WIDTH, 1)) <= 0.0_dp, 'no force in flight')
    end subroutine test_drop

    !> From the static settlement with v' = -V upwards: the linear spring-dashpot until the
    !> pressure k v + c v' reaches 0 (root of the closed form by bisection here), free
    !> flight until v = 0 (lift-off), back to v = 0 after 2 |v'|/g (touch-down).
    subroutine test_rebound(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        real(dp) :: tg(1), hist(WR_NOUT, 1), m, kk, cc, wn, z, wd, vv, lo, hi, mid, tq, vq, &
                    vdq, tau, t_lo, vd_lo
        integer :: stat, it
        call cylinder_model(1.0e9_dp, model, stat, xi=0.05_dp, damping_ref=DAMP_VERTICAL)
        m = model%body%mass
        kk = model%k * pi
        cc = model%c * pi
        wn = sqrt(kk / m)
        z = cc / (2.0_dp * sqrt(kk * m))
        wd = wn * sqrt(1.0_dp - z * z)
        vv = 0.2_dp
        ! q(t) A = k A (v_s + u) + c A u', u = -V e^(-z wn t) sin(wd t)/wd
        lo = 0.0_dp
        hi = pi / wd
        do it = 1, 200
            mid = 0.5_dp * (lo + hi)
            if (q_of(mid) > 0.0_dp) then
                lo = mid
            else
                hi = mid
            end if
        end do
        tq = lo
        call state_at(tq, vq, vdq)
        ! v_q + v'_q tau + g tau^2/2 = 0, the smaller root (v'_q < 0 < v_q)
        tau = 2.0_dp * vq / (-vdq + sqrt(vdq * vdq - 2.0_dp * g * vq))
        t_lo = tq + tau
        vd_lo = vdq + g * tau
        tg = [0.2_dp]
        call winkler_rock(model, tg, hist, run, stat, v_rate0=-vv, rtol=1.0e-11_dp)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, run%t_lift_off, t_lo, atol=1.0e-9_dp, rtol=0.0_dp, &
                   message='lift-off time')
        if (allocated(error)) return
        call check(error, run%t_touch_down, t_lo + 2.0_dp * abs(vd_lo) / g, atol=1.0e-9_dp, &
                   rtol=0.0_dp, message='touch-down time')

    contains

        subroutine state_at(t, v, vd)
            real(dp), intent(in) :: t
            real(dp), intent(out) :: v, vd
            real(dp) :: e
            e = exp(-z * wn * t)
            v = model%v_static - vv * e * sin(wd * t) / wd
            vd = -vv * e * (cos(wd * t) - z * wn / wd * sin(wd * t))
        end subroutine state_at

        function q_of(t) result(q)
            real(dp), intent(in) :: t
            real(dp) :: q, v, vd
            call state_at(t, v, vd)
            q = kk * v + cc * vd
        end function q_of

    end subroutine test_rebound

    !> One sine cycle of T = 19 s and peak a_p: at t = T/4 (a_g = a_p, rates ~ 0) theta is
    !> the static pushover tilt at F = m a_p, from the thesis's closed forms after uplift
    !> (written here): theta(b) = asin(2 W/(k Phi(b)))/2, M(b) = k sin cos^2 (J2 - c J1),
    !> F = (M - W h sin)/(h cos), with the contact width b solved by bisection.
    !> Tolerance 4e-3 relative: xi = 0.2 damps the start transient within a second, and
    !> the inertia of the slow motion remains, (omega/omega_t)^2 ~ 7e-4 of F with omega_t
    !> the frequency of the tangent stiffness, which at F = 0.2 W is a quarter of the secant
    !> one, so theta is 4 times more sensitive (measured: 2.5e-3, the same for xi = 0.05
    !> and 0.5: no damping effect).
    subroutine test_quasi_static(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        type(pulse_t) :: pl
        real(dp) :: tg(1), hist(WR_NOUT, 1), w, kk, ft, blo, bhi, bm, th_ref, bpk, fpk, fb
        integer :: stat, it, i
        call cylinder_model(1.0e9_dp, model, stat, xi=0.2_dp)
        call check(error, stat == 0, 'model')
        if (allocated(error)) return
        w = model%body%weight
        kk = model%k
        ft = 0.2_dp * w
        ! the peak of F(b) on a scan, then bisection on the rising branch [b_peak, 2R]
        bpk = 2.0_dp
        fpk = -huge(1.0_dp)
        do i = 1, 2000
            bm = 2.0_dp * real(i, dp) / 2000.0_dp
            fb = force(bm)
            if (fb > fpk) then
                fpk = fb
                bpk = bm
            end if
        end do
        call check(error, fpk > ft .and. force(2.0_dp) < ft, 'F = 0.2 W after uplift, before' &
                   //' the peak')
        if (allocated(error)) return
        blo = bpk
        bhi = 2.0_dp
        do it = 1, 200
            bm = 0.5_dp * (blo + bhi)
            if (force(bm) > ft) then
                blo = bm
            else
                bhi = bm
            end if
        end do
        th_ref = theta_of(blo)
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 19.0_dp
        pl%amp = ft / model%body%mass
        tg = [19.0_dp / 4.0_dp]
        call winkler_rock(model, tg, hist, run, stat, pulse=pl, rtol=1.0e-8_dp)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, hist(WR_OUT_THETA, 1), th_ref, rtol=4.0e-3_dp, &
                   message='theta at the peak vs static')
        if (allocated(error)) return
        call check(error, hist(WR_OUT_WIDTH, 1), blo, rtol=2.0e-3_dp, &
                   message='contact width vs static')

    contains

        pure function theta_of(b) result(th)
            real(dp), intent(in) :: b
            real(dp) :: th, c, s, x
            c = 1.0_dp - b
            s = sqrt(2.0_dp * b - b * b)
            x = 2.0_dp * w / (kk * ((2.0_dp / 3.0_dp) * s**3 + c * c * s - c * acos(c)))
            ! beyond the end of the branch (no equilibrium at this b): past pi/4
            th = 0.25_dp * pi
            if (x <= 1.0_dp) th = 0.5_dp * asin(x)
        end function theta_of

        pure function force(b) result(f)
            real(dp), intent(in) :: b
            real(dp) :: f, c, s, j1, j2, th, mm
            c = 1.0_dp - b
            s = sqrt(2.0_dp * b - b * b)
            j1 = (2.0_dp / 3.0_dp) * s**3
            j2 = 0.25_dp * (0.5_dp * pi - asin(c)) - 0.25_dp * c * (2.0_dp * c * c - 1.0_dp) * s
            th = theta_of(b)
            mm = kk * sin(th) * cos(th)**2 * (j2 - c * j1)
            f = (mm - w * 3.0_dp * sin(th)) / (3.0_dp * cos(th))
        end function force

    end subroutine test_quasi_static

    !> As test_quasi_static, checked on the force: the static force at the tilt of the
    !> slow run (T = 19 s, F = 0.2 W at t = T/4) is F = 0.2 W to 2e-3 (the inertia,
    !> (omega/omega_t)^2 ~ 1e-3 of F). Block b = 1 m, alpha = 0.8 m, h = 3 m: the thesis's
    !> closed form after uplift, b' = sqrt(2 W/(alpha k sin 2 theta)),
    !> M = alpha k sin cos^2 b'^2 (3 b - b')/3 (written here), and block_winkler_pushover;
    !> the cylinder with varying k: winkler_pushover with K_VARYING.
    subroutine test_quasi_static_more(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: body
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        type(winkler_pushover_t) :: res
        type(pulse_t) :: pl
        real(dp) :: tg(1), hist(WR_NOUT, 1), curve(1, WP_NCOL), w, th, bp, mm, f
        integer :: stat
        call block_props(1.0_dp, 3.0_dp, 30000.0_dp, g, body, stat)
        call winkler_model(body, 1.0e9_dp, model, stat, alpha=0.8_dp, xi=0.2_dp)
        call check(error, stat == 0, 'block model')
        if (allocated(error)) return
        w = body%weight
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 19.0_dp
        pl%amp = 0.2_dp * g
        tg = [19.0_dp / 4.0_dp]
        call winkler_rock(model, tg, hist, run, stat, pulse=pl, rtol=1.0e-8_dp)
        call check(error, stat == 0, 'block run')
        if (allocated(error)) return
        th = hist(WR_OUT_THETA, 1)
        bp = sqrt(2.0_dp * w / (0.8_dp * 1.0e9_dp * sin(2.0_dp * th)))
        call check(error, bp < 2.0_dp, 'block uplifted')
        if (allocated(error)) return
        mm = 0.8_dp * 1.0e9_dp * sin(th) * cos(th)**2 * bp * bp * (3.0_dp - bp) / 3.0_dp
        f = (mm - w * 3.0_dp * sin(th)) / (3.0_dp * cos(th))
        call check(error, f, 0.2_dp * w, rtol=2.0e-3_dp, message='block: closed-form F(theta)')
        if (allocated(error)) return
        call check(error, hist(WR_OUT_WIDTH, 1), bp, rtol=2.0e-3_dp, message="block: b'")
        if (allocated(error)) return
        call block_winkler_pushover(1.0_dp, 0.8_dp, 3.0_dp, w, 1.0e9_dp, [th], curve, res, stat)
        call check(error, stat == 0, 'block pushover')
        if (allocated(error)) return
        call check(error, curve(1, WP_FORCE), 0.2_dp * w, rtol=2.0e-3_dp, &
                   message='block: pushover F(theta)')
        if (allocated(error)) return
        call cylinder_model(1.0e9_dp, model, stat, xi=0.2_dp, k_method=K_VARYING)
        call check(error, stat == 0, 'varying-k model')
        if (allocated(error)) return
        w = model%body%weight
        pl%amp = 0.2_dp * g
        call winkler_rock(model, tg, hist, run, stat, pulse=pl, rtol=1.0e-8_dp)
        call check(error, stat == 0, 'varying-k run')
        if (allocated(error)) return
        call winkler_pushover(1.0_dp, 3.0_dp, w, 1.0e9_dp, [hist(WR_OUT_THETA, 1)], curve, res, &
                              stat, k_method=K_VARYING)
        call check(error, stat == 0, 'varying-k pushover')
        if (allocated(error)) return
        call check(error, curve(1, WP_FORCE), 0.2_dp * w, rtol=2.0e-3_dp, &
                   message='varying k: pushover F(theta)')
    end subroutine test_quasi_static_more

    !> One sine cycle, 0.25 g, T = 1 s, 20 s of rocking with impacts: E + D = E_0 + W_in at
    !> every output to 1e-6 of the energy scale; W_in against the trapezoidal rule of
    !> m a_g h cos(theta) theta' on the output grid (1e-3: the rule's own error).
    subroutine test_energy(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        type(pulse_t) :: pl
        integer, parameter :: n = 20001
        real(dp), allocatable :: tg(:), hist(:, :)
        real(dp) :: scale, wq, p1, p0, bal
        integer :: stat, i
        call cylinder_model(1.0e9_dp, model, stat, xi=0.003_dp)
        allocate(tg(n), hist(WR_NOUT, n))
        do i = 1, n
            tg(i) = 0.001_dp * (i - 1)
        end do
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 1.0_dp
        pl%amp = 0.25_dp * g
        call winkler_rock(model, tg, hist, run, stat, pulse=pl)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, run%n_impacts >= 2, 'impacts')
        if (allocated(error)) return
        call check(error, run%energy_error < 1.0e-6_dp, 'energy error of the run')
        if (allocated(error)) return
        scale = maxval(abs(hist(WR_OUT_ENERGY, :) - hist(WR_OUT_ENERGY, 1)))
        bal = 0.0_dp
        wq = 0.0_dp
        p0 = 0.0_dp
        do i = 1, n
            bal = max(bal, abs(hist(WR_OUT_ENERGY, i) + hist(WR_OUT_DISSIPATED, i) &
                               - hist(WR_OUT_ENERGY, 1) - hist(WR_OUT_WORK, i)))
            p1 = model%body%mass * hist(WR_OUT_ACCEL, i) * model%body%h &
                 * cos(hist(WR_OUT_THETA, i)) * hist(WR_OUT_THETA_RATE, i)
            if (i > 1) wq = wq + 0.5_dp * (tg(i) - tg(i - 1)) * (p0 + p1)
            p0 = p1
        end do
        call check(error, bal / max(scale, hist(WR_OUT_WORK, n)) < 1.0e-6_dp, &
                   'E + D - E0 - W_in at the outputs')
        if (allocated(error)) return
        call check(error, hist(WR_OUT_WORK, n), wq, rtol=1.0e-3_dp, &
                   message='input work vs quadrature')
        if (allocated(error)) return
        call check(error, minval(hist(WR_OUT_DISSIPATED, :)) > -1.0e-6_dp * scale, &
                   'dissipated >= 0')
    end subroutine test_energy

    !> The one-sine pulse (0.25 g, T = 1 s) sampled every 0.5 ms, passed as a record in g
    !> with g_rec: theta(t) over 3 s agrees with the pulse run to 1e-3 of theta_max (the
    !> linear interpolation of the samples changes a_g by (pi dt/T)^2/2 ~ 1e-5 of a_p).
    subroutine test_record(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run1, run2
        type(pulse_t) :: pl
        integer, parameter :: n = 301, ns = 2001
        real(dp) :: tg(n), h1(WR_NOUT, n), h2(WR_NOUT, n), acc(ns), dt
        integer :: stat, i
        call cylinder_model(1.0e9_dp, model, stat, xi=0.003_dp)
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 1.0_dp
        pl%amp = 0.25_dp * g
        dt = 0.0005_dp
        do i = 1, ns
            acc(i) = 0.25_dp * g * sin(2.0_dp * pi * dt * (i - 1))   ! m/s^2
        end do
        acc(ns) = 0.0_dp
        do i = 1, n
            tg(i) = 0.01_dp * (i - 1)
        end do
        call winkler_rock(model, tg, h1, run1, stat, pulse=pl)
        call check(error, stat == 0, 'pulse run')
        if (allocated(error)) return
        ! samples in m/s^2: a record in units of g_rec = 1 m/s^2 (the body's g is 9.81)
        call winkler_rock(model, tg, h2, run2, stat, accel=acc(1:2001), dt=dt, g_rec=1.0_dp)
        call check(error, stat == 0, 'record run')
        if (allocated(error)) return
        call check(error, run1%theta_max > 1.0e-3_dp, 'rocks')
        if (allocated(error)) return
        call check(error, maxval(abs(h1(WR_OUT_THETA, :) - h2(WR_OUT_THETA, :))) &
                   < 1.0e-3_dp * run1%theta_max, 'theta(t), record vs pulse')
        if (allocated(error)) return
        call check(error, h2(WR_OUT_ACCEL, 26), 0.25_dp * g, rtol=1.0e-4_dp, &
                   message='a_g of the record at T/4')
    end subroutine test_record

    !> Free rocking from rest with theta' such that the kinetic energy is 0.9 B (B the
    !> barrier U_min(theta_ov) - U_min(0)): decided safe at once (t_safe = 0), and a run on
    !> to 10 s never reaches theta_ov. With 1.5 B (and c = 0) it overturns without impact.
    subroutine test_energy_criterion(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        integer, parameter :: n = 2001
        real(dp) :: tg(n), hist(WR_NOUT, n), b, v_ov, i_o, w0
        integer :: stat, i
        call cylinder_model(1.0e9_dp, model, stat, c=0.0_dp)
        call winkler_barrier(model, b, v_ov, stat)
        call check(error, stat == 0 .and. b > 0.0_dp, 'barrier')
        if (allocated(error)) return
        i_o = model%body%j_g + model%body%mass * model%body%h**2
        do i = 1, n
            tg(i) = 0.005_dp * (i - 1)
        end do
        w0 = sqrt(2.0_dp * 0.9_dp * b / i_o)
        call winkler_rock(model, tg, hist, run, stat, theta_rate0=w0)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, run%outcome == WR_RUN_SAFE .and. abs(run%t_safe) <= 0.0_dp, &
                   'decided safe at once')
        if (allocated(error)) return
        call check(error, maxval(abs(hist(WR_OUT_THETA, :))) < model%theta_overturn, &
                   'stays inside theta_ov')
        if (allocated(error)) return
        call check(error, run%n_impacts >= 2, 'rocks')
        if (allocated(error)) return
        w0 = sqrt(2.0_dp * 1.5_dp * b / i_o)
        call winkler_rock(model, tg, hist, run, stat, theta_rate0=w0)
        call check(error, stat == 0, 'run')
        if (allocated(error)) return
        call check(error, run%outcome == WR_RUN_OVERTURN_NO_IMPACT, 'overturns')
        if (allocated(error)) return
        call check(error, abs(hist(WR_OUT_THETA, n)), 0.5_dp * pi, rtol=0.0_dp, &
                   message='on its side')
    end subroutine test_energy_criterion

    !> The Jacobian against central differences (steps scaled to each state component,
    !> Richardson-extrapolated): full contact, partial contact (delta root), a pressure root
    !> (dashpot), both roots, no contact, the rectangle, the varying k (its dk/db is itself
    !> a difference: looser).
    subroutine test_jacobian(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: mc, mr, mv
        type(rocking_body_t) :: body
        real(dp) :: y(6, 7), f(6), jac(6, 6), jfd(6, 6), vs
        integer :: stat, j
        call cylinder_model(1.0e9_dp, mc, stat, xi=0.05_dp)
        call cylinder_model(1.0e9_dp, mv, stat, xi=0.05_dp, k_method=K_VARYING)
        call block_props(1.0_dp, 3.0_dp, 30000.0_dp, g, body, stat)
        call winkler_model(body, 1.0e9_dp, mr, stat, alpha=0.8_dp, xi=0.05_dp)
        call check(error, stat == 0, 'models')
        if (allocated(error)) return
        vs = mc%v_static
        y(:, 1) = [vs, 1.0e-6_dp, 1.0e-4_dp, 1.0e-4_dp, 0.0_dp, 0.0_dp]     ! full contact
        y(:, 2) = [1.0e-6_dp, 0.05_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]       ! delta root
        y(:, 3) = [vs, 5.0e-5_dp, -2.0e-2_dp, 1.0e-3_dp, 0.0_dp, 0.0_dp]     ! q root
        y(:, 4) = [2.0e-5_dp, -0.01_dp, 1.0e-2_dp, -0.5_dp, 0.0_dp, 0.0_dp]  ! both roots
        y(:, 5) = [-1.0e-3_dp, 0.01_dp, 0.1_dp, 0.3_dp, 0.0_dp, 0.0_dp]      ! no contact
        y(:, 6) = [1.0e-5_dp, 0.02_dp, -1.0e-3_dp, 0.1_dp, 0.0_dp, 0.0_dp]
        y(:, 7) = [vs, 2.0e-4_dp, 1.0e-3_dp, 0.01_dp, 0.0_dp, 0.0_dp]
        do j = 1, 5
            call winkler_rhs_jacobian(mc, 2.0_dp, y(:, j), f, jac)
            call fd_jacobian(mc, y(:, j), jfd)
            call compare(jac, jfd, 1.0e-6_dp, 'circle, state '//achar(48 + j))
            if (allocated(error)) return
        end do
        call winkler_rhs_jacobian(mr, 2.0_dp, y(:, 6), f, jac)
        call fd_jacobian(mr, y(:, 6), jfd)
        call compare(jac, jfd, 1.0e-6_dp, 'rectangle, partial contact')
        if (allocated(error)) return
        do j = 6, 7
            call winkler_rhs_jacobian(mv, 2.0_dp, y(:, j), f, jac)
            call fd_jacobian(mv, y(:, j), jfd)
            call compare(jac, jfd, 1.0e-4_dp, 'varying k, state '//achar(48 + j))
            if (allocated(error)) return
        end do

    contains

        subroutine fd_jacobian(model, y0, jfd)
            type(winkler_model_t), intent(in) :: model
            real(dp), intent(in) :: y0(6)
            real(dp), intent(out) :: jfd(6, 6)
            real(dp) :: sc(6), d1(6), d2(6)
            integer :: i
            sc = [1.0e-6_dp, 1.0e-6_dp, 1.0e-4_dp, 1.0e-4_dp, 1.0_dp, 1.0_dp]
            do i = 1, 6
                d1 = diff(model, y0, i, 1.0e-3_dp * max(abs(y0(i)), sc(i)))
                d2 = diff(model, y0, i, 0.5e-3_dp * max(abs(y0(i)), sc(i)))
                jfd(:, i) = (4.0_dp * d2 - d1) / 3.0_dp
            end do
        end subroutine fd_jacobian

        function diff(model, y0, i, hstep) result(d)
            type(winkler_model_t), intent(in) :: model
            real(dp), intent(in) :: y0(6)
            integer, intent(in) :: i
            real(dp), intent(in) :: hstep
            real(dp) :: d(6), yp(6), fp(6), fm(6), dum(6, 6)
            yp = y0
            yp(i) = yp(i) + hstep
            call winkler_rhs_jacobian(model, 2.0_dp, yp, fp, dum)
            yp = y0
            yp(i) = yp(i) - hstep
            call winkler_rhs_jacobian(model, 2.0_dp, yp, fm, dum)
            d = (fp - fm) / (2.0_dp * hstep)
        end function diff

        subroutine compare(a, b, tol, what)
            real(dp), intent(in) :: a(6, 6), b(6, 6), tol
            character(len=*), intent(in) :: what
            integer :: i
            do i = 3, 6
                call check(error, maxval(abs(a(i, :) - b(i, :))) <= tol * max(maxval(abs(a(i, :))), &
                           tiny(1.0_dp)), 'Jacobian row '//achar(48 + i)//': '//what)
                if (allocated(error)) return
            end do
        end subroutine compare

    end subroutine test_jacobian

    !> One sine cycle at f_p = 0.5 Hz (the rigid threshold overturns without impact, so
    !> the restitution, Housner's on rigid ground and the dashpots' on Winkler soil, does
    !> not enter): the overturning PGA on Winkler soil (bisection on 1 x 1 maps here) for
    !> k = 1e8, 1e9, 1e10 N/m^3 comes closer to the rigid-ground threshold of
    !> seispulse_cylinder's overturning_threshold as k grows (the gap about halves per
    !> decade of k).
    subroutine test_rigid_limit(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: body
        type(winkler_model_t) :: model
        real(dp) :: rigid(1), thr(3), lo, hi, mid, no_grid(0), no_hist(WR_NOUT, 0)
        type(winkler_run_t) :: run
        type(pulse_t) :: pl
        integer :: stat, i, it, cls(1, 1)
        real(dp), parameter :: ks(3) = [1.0e8_dp, 1.0e9_dp, 1.0e10_dp]
        call cylinder_props(1.0_dp, 3.0_dp, 2500.0_dp * pi * 6.0_dp, g, body, stat)
        call overturning_threshold(body, PULSE_SINE_CYCLE, [0.5_dp], rigid, stat)
        call check(error, stat == 0 .and. ieee_is_finite(rigid(1)), 'rigid threshold')
        if (allocated(error)) return
        do i = 1, 3
            call winkler_model(body, ks(i), model, stat, xi=0.003_dp)
            lo = 0.3_dp * rigid(1)
            hi = 2.0_dp * rigid(1)
            do it = 1, 14
                mid = 0.5_dp * (lo + hi)
                call winkler_overturning_map(model, PULSE_SINE_CYCLE, [0.5_dp], [mid], &
                                             MAP_AXES_DIMENSIONAL, cls, stat)
                if (stat /= 0) exit
                if (cls(1, 1) > 0) then
                    hi = mid
                else
                    lo = mid
                end if
            end do
            call check(error, stat == 0, 'map cell')
            if (allocated(error)) return
            thr(i) = hi
            if (i == 2) then
                ! the map's cells and winkler_rock agree on both sides of the threshold
                pl%kind = PULSE_SINE_CYCLE
                pl%duration = 2.0_dp
                pl%amp = hi * g
                call winkler_rock(model, no_grid, no_hist, run, stat, pulse=pl, &
                                  t_max=ieee_value(1.0_dp, ieee_positive_inf))
                call check(error, stat == 0 .and. run%outcome >= WR_RUN_OVERTURN_NO_IMPACT &
                           .and. run%outcome <= WR_RUN_OVERTURN_IMPACTS, 'run at hi overturns')
                if (allocated(error)) return
                pl%amp = lo * g
                call winkler_rock(model, no_grid, no_hist, run, stat, pulse=pl, &
                                  t_max=ieee_value(1.0_dp, ieee_positive_inf))
                call check(error, stat == 0 .and. run%outcome == WR_RUN_SAFE, 'run at lo safe')
                if (allocated(error)) return
            end if
        end do
        call check(error, abs(thr(2) - rigid(1)) < abs(thr(1) - rigid(1)) .and. &
                   abs(thr(3) - rigid(1)) < abs(thr(2) - rigid(1)), 'closer as k grows')
        if (allocated(error)) return
        call check(error, thr(3), rigid(1), rtol=0.15_dp, message='k = 1e10 near rigid')
    end subroutine test_rigid_limit

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: body, blk
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        type(pulse_t) :: pl
        real(dp) :: hist(WR_NOUT, 2), bad(2, 1), nan
        integer :: stat, cls(1, 1)
        character(len=200) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        call cylinder_props(1.0_dp, 3.0_dp, 1000.0_dp, g, body, stat)
        call block_props(1.0_dp, 3.0_dp, 1000.0_dp, g, blk, stat)
        msg = ''
        call winkler_model(body, -1.0_dp, model, stat, msg)
        call check(error, stat /= 0 .and. index(msg, 'k =') > 0, 'k < 0')
        if (allocated(error)) return
        call winkler_model(body, nan, model, stat, msg)
        call check(error, stat /= 0, 'k NaN')
        if (allocated(error)) return
        msg = ''
        call winkler_model(blk, 1.0e9_dp, model, stat, msg)
        call check(error, stat /= 0 .and. index(msg, 'alpha') > 0, 'block without alpha')
        if (allocated(error)) return
        msg = ''
        call winkler_model(body, 1.0e9_dp, model, stat, msg, xi=0.01_dp, c=1.0_dp)
        call check(error, stat /= 0 .and. index(msg, 'c, xi') > 0, 'c and xi')
        if (allocated(error)) return
        msg = ''
        call winkler_model(body, 1.0_dp, model, stat, msg, xi=0.01_dp)
        call check(error, stat /= 0 .and. index(msg, 'xi') > 0, 'too soft for DAMP_ROCKING')
        if (allocated(error)) return
        call winkler_model(body, 1.0e9_dp, model, stat, msg, xi=-0.1_dp)
        call check(error, stat /= 0, 'xi < 0')
        if (allocated(error)) return
        call winkler_model(body, 1.0e9_dp, model, stat, msg, k_method=3)
        call check(error, stat /= 0, 'k_method')
        if (allocated(error)) return
        call winkler_model(body, 1.0e9_dp, model, stat, msg, xi=0.01_dp, damping_ref=5)
        call check(error, stat /= 0, 'damping_ref')
        if (allocated(error)) return
        call winkler_model(body, 1.0e9_dp, model, stat, msg)
        call check(error, stat == 0, 'good model')
        if (allocated(error)) return
        call winkler_rock(model, [0.0_dp, 1.0_dp], bad, run, stat, msg)
        call check(error, stat /= 0 .and. index(msg, 'hist') > 0, 'hist shape')
        if (allocated(error)) return
        call winkler_rock(model, [1.0_dp, 0.5_dp], hist, run, stat, msg)
        call check(error, stat /= 0, 't_grid not ascending')
        if (allocated(error)) return
        msg = ''
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, rtol=1.0_dp)
        call check(error, stat /= 0 .and. index(msg, 'rtol') > 0, 'rtol')
        if (allocated(error)) return
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, theta0=2.0_dp)
        call check(error, stat /= 0, 'theta0')
        if (allocated(error)) return
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, pulse=pl, &
                          accel=[0.0_dp, 0.1_dp], dt=0.01_dp)
        call check(error, stat /= 0 .and. index(msg, 'not both') > 0, 'pulse and record')
        if (allocated(error)) return
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, accel=[0.0_dp, 0.1_dp])
        call check(error, stat /= 0 .and. index(msg, 'dt') > 0, 'record without dt')
        if (allocated(error)) return
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, t_max=-1.0_dp)
        call check(error, stat /= 0, 't_max')
        if (allocated(error)) return
        call winkler_overturning_map(model, PULSE_MP, [1.0_dp], [1.0_dp], MAP_AXES_DIMENSIONAL, &
                                     cls, stat, msg)
        call check(error, stat /= 0, 'map kind')
        if (allocated(error)) return
        call winkler_overturning_map(model, PULSE_SINE_CYCLE, [1.0_dp], [1.0_dp], 7, cls, stat, &
                                     msg)
        call check(error, stat /= 0, 'map axes')
        if (allocated(error)) return
        call winkler_overturning_map(model, PULSE_SINE_CYCLE, [-1.0_dp], [1.0_dp], &
                                     MAP_AXES_DIMENSIONAL, cls, stat, msg)
        call check(error, stat /= 0, 'map x')
        if (allocated(error)) return
        call check(error, winkler_outcome_name(WR_RUN_SAFE) == 'safe' .and. &
                   winkler_output_name(WR_OUT_THETA) == 'theta' .and. &
                   winkler_output_name(99) == '', 'names')
        if (allocated(error)) return
        msg = ''
        call winkler_model(body, 1.0e9_dp, model, stat, msg, k_method=K_VARYING, reading=99)
        call check(error, stat /= 0 .and. index(msg, 'reading') > 0, 'reading')
        if (allocated(error)) return
        call winkler_model(body, 1.0e9_dp, model, stat, msg)
        msg = ''
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, v_rate0=1.0e200_dp)
        call check(error, stat /= 0 .and. index(msg, 'v_rate0') > 0, 'v_rate0 huge')
        if (allocated(error)) return
        msg = ''
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg, v0=1.0e150_dp)
        call check(error, stat /= 0 .and. index(msg, 'v0') > 0, 'v0 huge')
        if (allocated(error)) return
        ! a grazing start: v0 = 0 with a subnormal tilt (1/sin theta in the Jacobian)
        call winkler_rock(model, [0.0_dp, 0.01_dp], hist, run, stat, msg, v0=0.0_dp, &
                          theta0=1.0e-310_dp)
        call check(error, stat == 0, 'grazing start runs')
        if (allocated(error)) return
        model%k = 2.0_dp * model%k
        msg = ''
        call winkler_rock(model, [0.0_dp, 1.0_dp], hist, run, stat, msg)
        call check(error, stat /= 0 .and. index(msg, 'winkler_model') > 0, 'k edited')
    end subroutine test_bad_input

    !> The end of the excitation is the end of the run (no outputs after it): the
    !> overturning rule of the free motion still decides there (it gave "time limit"), and
    !> free motion with neither outputs nor t_max runs until its outcome is known.
    subroutine test_end_of_excitation(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run, run_inf
        type(pulse_t) :: pl
        real(dp) :: no_grid(0), no_hist(WR_NOUT, 0)
        integer :: stat
        call cylinder_model(1.0e9_dp, model, stat, xi=0.003_dp)
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 2.0_dp * pi / (3.0_dp * model%body%p)
        pl%amp = 3.4_dp * g * tan(model%body%theta_c)
        call winkler_rock(model, no_grid, no_hist, run, stat, pulse=pl)
        call check(error, stat, 0, 'run')
        if (allocated(error)) return
        call winkler_rock(model, no_grid, no_hist, run_inf, stat, pulse=pl, &
                          t_max=ieee_value(1.0_dp, ieee_positive_inf))
        call check(error, run_inf%outcome >= WR_RUN_OVERTURN_NO_IMPACT .and. &
                   run_inf%outcome <= WR_RUN_OVERTURN_IMPACTS, 'overturns (t_max = inf)')
        if (allocated(error)) return
        call check(error, run%outcome, run_inf%outcome, 'the same outcome at the pulse end')
        if (allocated(error)) return
        call winkler_rock(model, no_grid, no_hist, run, stat, theta0=0.2_dp)
        call check(error, stat, 0, 'free run')
        if (allocated(error)) return
        call check(error, run%outcome /= WR_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp, &
                   'free motion decided')
    end subroutine test_end_of_excitation

    !> Varying k has no energy criterion: a cell that still stands at the end of its window
    !> is safe (0), not undecided (-1), and a strong pulse still overturns. theta_max is the
    !> largest |theta| of the motion: not below any output sample, and equal to the turning
    !> point located on the dense output (not a sample near it).
    subroutine test_varying_map(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(winkler_run_t) :: run
        type(pulse_t) :: pl
        real(dp) :: t(2001), hist(WR_NOUT, 2001)
        integer :: stat, cls(2, 1), i, i_max
        call cylinder_model(1.0e9_dp, model, stat, xi=0.003_dp, k_method=K_VARYING)
        call check(error, stat, 0, 'model')
        if (allocated(error)) return
        call winkler_overturning_map(model, PULSE_SINE_CYCLE, [0.5_dp], [0.05_dp, 3.0_dp], &
                                     MAP_AXES_DIMENSIONAL, cls, stat)
        call check(error, stat, 0, 'map')
        if (allocated(error)) return
        call check(error, cls(1, 1), 0, 'a weak pulse: safe')
        if (allocated(error)) return
        call check(error, cls(2, 1) > 0, 'a strong pulse overturns')
        if (allocated(error)) return
        pl%kind = PULSE_SINE_CYCLE
        pl%duration = 2.0_dp
        pl%amp = 0.3_dp * g
        do i = 1, size(t)
            t(i) = 4.0_dp * real(i - 1, dp) / real(size(t) - 1, dp)
        end do
        call winkler_rock(model, t, hist, run, stat, pulse=pl)
        call check(error, stat, 0, 'run')
        if (allocated(error)) return
        i_max = maxloc(abs(hist(WR_OUT_THETA, :)), 1)
        call check(error, run%theta_max >= abs(hist(WR_OUT_THETA, i_max)), 'not below a sample')
        if (allocated(error)) return
        ! at the largest sample theta' changes sign within one sample interval: the located
        ! extreme is within the curvature of that interval
        call check(error, run%theta_max - abs(hist(WR_OUT_THETA, i_max)) &
                   <= 0.5_dp * abs(hist(WR_OUT_THETA_RATE, i_max)) * (t(2) - t(1)) + 1.0e-15_dp, &
                   'close to the largest sample')
    end subroutine test_varying_map

    !> A Ricker pulse whose side lobes stay below the rigid uplift acceleration but above
    !> the kern level (an edge lifts at about a quarter of it): the micro-rocking they cause
    !> (|theta| ~ 1e-4 rad for k = 1e10, 1e-5 for 1e11, against theta_c = 0.32) is not an
    !> impact, so the class is the rigid one (overturning without impact) for stiff soil,
    !> where counting every crossing after an edge lift gave "after one impact".
    subroutine test_kern_rocking(error)
        type(test_error), allocatable, intent(out) :: error
        type(winkler_model_t) :: model
        type(rocking_body_t) :: body
        integer :: stat, cls(1, 1), rigid(1, 1), i
        real(dp), parameter :: ks(2) = [1.0e10_dp, 1.0e11_dp]
        call cylinder_props(1.0_dp, 3.0_dp, 2500.0_dp * pi * 6.0_dp, g, body, stat)
        call body_overturning_map(body, PULSE_RICKER, [1.0_dp], [1.5_dp], &
                                  MAP_AXES_DIMENSIONLESS, rigid, stat)
        call check(error, stat == 0 .and. rigid(1, 1) == 1, 'rigid: overturns without impact')
        if (allocated(error)) return
        do i = 1, 2
            call winkler_model(body, ks(i), model, stat, xi=0.003_dp)
            call winkler_overturning_map(model, PULSE_RICKER, [1.0_dp], [1.5_dp], &
                                         MAP_AXES_DIMENSIONLESS, cls, stat)
            call check(error, stat, 0, 'map')
            if (allocated(error)) return
            call check(error, cls(1, 1), rigid(1, 1), 'Winkler class = rigid class')
            if (allocated(error)) return
        end do
    end subroutine test_kern_rocking

end module test_winkler_rock
