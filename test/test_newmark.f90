!> Newmark rigid-block sliding on records: the exact rule against the event-driven
!> integrator of seispulse_sliding_sim (slides, extremes, histories), exactness on
!> piecewise-linear input (triangles, linear upsampling), second-order convergence to
!> the exponential-pulse closed forms of seispulse_sliding_closed, SLAMMER's loop against its
!> closed form for constant acceleration and its first-order convergence to the exact
!> answer, the incline factors, and bad input. (SLAMMER 1.1's own 180 results are
!> checked in test/python/test_newmark_slammer.py, with the records of pyslammer.)
module test_newmark
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_pulses, only: pulse_eval, triangular_pulse, exp_pulse
    use seispulse_sliding_sim, only: friction_t, stickslip_result_t, stickslip_record, &
                                   stickslip_pulse
    use seispulse_sliding_closed, only: full_cycle_t, half_cycle_t, full_cycle, half_cycle, &
                                 inclined_resistances
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, &
                                 newmark_incline, NEWMARK_DOWN, NEWMARK_BOTH, NEWMARK_ASYM, &
                                 NEWMARK_EXACT, NEWMARK_SLAMMER
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_newmark

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp
    real(dp), parameter :: g0 = 9.80665_dp

contains

    subroutine collect_newmark(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('exact = event-driven integrator (down, both, asym)', &
                              test_against_stickslip), &
                 new_unittest('sampled triangle: exact at any dt', test_triangle_exact), &
                 new_unittest('linear upsampling leaves exact unchanged; SLAMMER -> exact', &
                              test_upsampling), &
                 new_unittest('exponential pulse: second order to the closed forms', &
                              test_exp_convergence), &
                 new_unittest('SLAMMER loop: constant acceleration in closed form', &
                              test_slammer_constant), &
                 new_unittest('symmetry: both-ways record inverted, one-way never negative', &
                              test_symmetry), &
                 new_unittest('incline: yields of Eq. 1.31, slips scaled by K per slide', &
                              test_incline), &
                 new_unittest('histories and intervals are consistent', test_histories), &
                 new_unittest('bad input is a status naming the parameter', test_bad_input)]
    end subroutine collect_newmark

    ! ---------------------------------------------------------------- helpers

    !> A deterministic strong-motion-like record (g): a sum of sines under an envelope.
    function synthetic(n, dt, seed) result(a)
        integer, intent(in) :: n, seed
        real(dp), intent(in) :: dt
        real(dp) :: a(n), t, env
        integer :: i, k
        real(dp), parameter :: freq(5) = [0.7_dp, 1.3_dp, 2.9_dp, 4.1_dp, 7.3_dp]
        real(dp), parameter :: amp(5) = [0.12_dp, 0.2_dp, 0.15_dp, 0.08_dp, 0.05_dp]
        do i = 1, n
            t = real(i - 1, dp) * dt
            env = (t / 3.0_dp)**2 * exp(2.0_dp - 2.0_dp * t / 3.0_dp)
            a(i) = 0.0_dp
            do k = 1, 5
                a(i) = a(i) + amp(k) * sin(2.0_dp * pi * freq(k) * t + 0.37_dp * k * seed)
            end do
            a(i) = 1.6_dp * env * a(i)
        end do
    end function synthetic

    function blk_of(mode, ky, ky_up, k_down, k_up) result(b)
        integer, intent(in) :: mode
        real(dp), intent(in) :: ky
        real(dp), intent(in), optional :: ky_up, k_down, k_up
        type(newmark_block_t) :: b
        b%mode = mode
        b%ky = ky
        b%ky_up = ky
        if (present(ky_up)) b%ky_up = ky_up
        if (present(k_down)) b%k_down = k_down
        if (present(k_up)) b%k_up = k_up
    end function blk_of

    subroutine run(error, accel, dt, b, method, g, res, label, u_hist, w_hist)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: accel(:), dt, g
        type(newmark_block_t), intent(in) :: b
        integer, intent(in) :: method
        type(newmark_result_t), intent(out) :: res
        character(len=*), intent(in) :: label
        real(dp), intent(out), optional :: u_hist(:), w_hist(:)
        integer :: stat
        character(len=200) :: msg
        msg = ''
        call newmark_rigid(accel, dt, b, method, g, res, stat, msg, u_hist, w_hist)
        call check(error, stat, SEISPULSE_SUCCESS, label//': status ('//trim(msg)//')')
    end subroutine run

    function linear_upsample(a, m) result(b)
        real(dp), intent(in) :: a(:)
        integer, intent(in) :: m
        real(dp) :: b((size(a) - 1) * m + 1)
        integer :: i, j
        do i = 1, size(a) - 1
            do j = 0, m - 1
                b((i - 1) * m + j + 1) = a(i) + (a(i + 1) - a(i)) * (real(j, dp) / m)
            end do
        end do
        b(size(b)) = a(size(a))
    end function linear_upsample

    ! ---------------------------------------------------------------- tests

    !> The exact rule solves the same problem as stickslip_record (accel in g; run with
    !> g = 1, so its u in g s^2 times g = 9.80665): slides, extremes and histories agree
    !> to rounding.
    subroutine test_against_stickslip(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 2400
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n), tg(n), ug(n), wg(n), uh(n), wh(n), ky, ky_up, scale
        real(dp) :: kys(4) = [0.02_dp, 0.07_dp, 0.15_dp, 0.3_dp]
        type(newmark_result_t) :: res
        type(stickslip_result_t) :: ref
        type(friction_t) :: fr
        integer :: seed, ik, mode, i, stat, j
        character(len=80) :: label
        real(dp) :: inf
        inf = ieee_value(inf, ieee_positive_inf)
        tg = [(real(i - 1, dp) * dt, i = 1, n)]
        do seed = 1, 3
            a = synthetic(n, dt, seed)
            do ik = 1, size(kys)
                ky = kys(ik)
                do mode = NEWMARK_DOWN, NEWMARK_ASYM
                    write(label, '(a, i0, a, f5.2, a, i0)') 'seed ', seed, ' ky ', ky, ' mode ', mode
                    select case (mode)
                    case (NEWMARK_DOWN)
                        ky_up = inf
                    case (NEWMARK_BOTH)
                        ky_up = ky
                    case default
                        ky_up = 1.8_dp * ky
                    end select
                    call run(error, a, dt, blk_of(mode, ky, 1.8_dp * ky), NEWMARK_EXACT, g0, &
                             res, trim(label), uh, wh)
                    if (allocated(error)) return
                    fr%ay_fwd = ky
                    fr%ay_rev = ky_up
                    call stickslip_record(a, dt, fr, 1.0_dp, ref, stat, t_grid=tg, u_grid=ug, &
                                          w_grid=wg)
                    call check(error, stat, SEISPULSE_SUCCESS, trim(label)//': stickslip')
                    if (allocated(error)) return
                    scale = g0 * max(ref%u_max, -ref%u_min, 1.0e-6_dp)
                    call check(error, size(res%slides), size(ref%slides), trim(label)//': slides')
                    if (allocated(error)) return
                    call check(error, res%final_disp, g0 * ref%u_final, atol=1.0e-12_dp * scale, &
                               message=trim(label)//': final')
                    if (allocated(error)) return
                    call check(error, res%u_max, g0 * ref%u_max, atol=1.0e-12_dp * scale, &
                               message=trim(label)//': u_max')
                    if (allocated(error)) return
                    call check(error, res%u_min, g0 * ref%u_min, atol=1.0e-12_dp * scale, &
                               message=trim(label)//': u_min')
                    if (allocated(error)) return
                    call check(error, res%t_end, ref%t_end, atol=1.0e-10_dp, &
                               message=trim(label)//': t_end')
                    if (allocated(error)) return
                    do j = 1, size(ref%slides)
                        call check(error, real(res%slides(j)%direction, dp), &
                                   real(ref%slides(j)%direction, dp), message=trim(label)//': dir')
                        if (allocated(error)) return
                        call check(error, res%slides(j)%t_start, ref%slides(j)%t_start, &
                                   atol=1.0e-10_dp, message=trim(label)//': onset')
                        if (allocated(error)) return
                        call check(error, res%slides(j)%t_stop, ref%slides(j)%t_stop, &
                                   atol=1.0e-10_dp, message=trim(label)//': stop')
                        if (allocated(error)) return
                        call check(error, res%slides(j)%u_stop, g0 * ref%slides(j)%u_stop, &
                                   atol=1.0e-12_dp * scale, message=trim(label)//': u at stop')
                        if (allocated(error)) return
                        call check(error, res%slides(j)%w_peak, g0 * ref%slides(j)%w_peak, &
                                   rtol=1.0e-10_dp, atol=1.0e-14_dp, message=trim(label)//': w_peak')
                        if (allocated(error)) return
                        call check(error, res%slides(j)%from_slip .eqv. ref%slides(j)%from_slip, &
                                   trim(label)//': from_slip')
                        if (allocated(error)) return
                    end do
                    call check(error, maxval(abs(uh - g0 * ug)) <= 1.0e-12_dp * scale, &
                               trim(label)//': u history')
                    if (allocated(error)) return
                    call check(error, maxval(abs(wh - g0 * wg)) <= 1.0e-11_dp * max(res%max_vel, &
                               1.0e-6_dp), trim(label)//': velocity history')
                    if (allocated(error)) return
                end do
            end do
        end do
    end subroutine test_against_stickslip

    !> A triangle sampled with its corners on samples is piecewise linear: the exact rule
    !> gives the pulse's event-driven answer at a coarse and a fine step alike.
    subroutine test_triangle_exact(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: dts(3) = [0.1_dp, 0.05_dp, 0.002_dp]
        real(dp), allocatable :: t(:), a(:), v(:), d(:)
        type(stickslip_result_t) :: ref
        type(newmark_result_t) :: res
        type(friction_t) :: fr
        integer :: k, n, i, stat
        ! 0.5 g peak at 0.4 s of a 1 s triangle, ky = 0.2 g (a free stop after the pulse)
        fr%ay_fwd = 0.2_dp * g0
        fr%ay_rev = 0.2_dp * g0
        call stickslip_pulse(triangular_pulse(0.5_dp * g0, 1.0_dp, 0.4_dp), fr, ref, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'triangle pulse')
        if (allocated(error)) return
        do k = 1, size(dts)
            n = nint(1.0_dp / dts(k)) + 1
            allocate(t(n), a(n), v(n), d(n))
            t = [(real(i - 1, dp) * dts(k), i = 1, n)]
            call pulse_eval(triangular_pulse(0.5_dp, 1.0_dp, 0.4_dp), t, a, v, d, stat)
            call run(error, a, dts(k), blk_of(NEWMARK_BOTH, 0.2_dp), NEWMARK_EXACT, g0, res, &
                     'triangle')
            if (allocated(error)) return
            call check(error, res%final_disp, ref%u_final, rtol=1.0e-13_dp, &
                       message='final displacement')
            if (allocated(error)) return
            call check(error, res%t_end, ref%t_end, rtol=1.0e-13_dp, message='stop time')
            if (allocated(error)) return
            call check(error, size(res%slides), 1, 'one slide')
            if (allocated(error)) return
            deallocate(t, a, v, d)
        end do
    end subroutine test_triangle_exact

    !> Linear interpolation between the samples is the exact rule's own model of the
    !> record, so upsampling changes nothing; SLAMMER's trapezoidal loop converges to
    !> the same answer at first order in dt.
    subroutine test_upsampling(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1200
        real(dp), parameter :: dt = 0.02_dp
        real(dp) :: a(n), e(3), ratio
        real(dp), allocatable :: b(:)
        type(newmark_result_t) :: ref, res
        integer :: mode, m, k
        a = synthetic(n, dt, 2)
        do mode = NEWMARK_DOWN, NEWMARK_BOTH
            call run(error, a, dt, blk_of(mode, 0.08_dp), NEWMARK_EXACT, g0, ref, 'coarse')
            if (allocated(error)) return
            call check(error, ref%max_disp > 1.0e-2_dp, 'the case slides (> 1 cm)')
            if (allocated(error)) return
            do m = 2, 5, 3
                b = linear_upsample(a, m)
                call run(error, b, dt / m, blk_of(mode, 0.08_dp), NEWMARK_EXACT, g0, res, 'fine')
                if (allocated(error)) return
                call check(error, res%final_disp, ref%final_disp, rtol=1.0e-11_dp, &
                           message='upsampled final')
                if (allocated(error)) return
                call check(error, res%max_disp, ref%max_disp, rtol=1.0e-11_dp, &
                           message='upsampled max')
                if (allocated(error)) return
                call check(error, size(res%slides), size(ref%slides), 'upsampled slides')
                if (allocated(error)) return
            end do
            ! SLAMMER's loop on the upsampled record: one way, its trapezoidal onsets and
            ! stops are O(dt), so at least first order over two halvings; two ways, each
            ! immediate reversal also loses half a step of a_g - ky (an O(dt) error with
            ! an O(1) jump in y), which converges slowly and not monotonically
            if (mode == NEWMARK_DOWN) then
                do k = 1, 3
                    m = 8 * 2**(k - 1)
                    b = linear_upsample(a, m)
                    call run(error, b, dt / m, blk_of(mode, 0.08_dp), NEWMARK_SLAMMER, g0, &
                             res, 'slammer fine')
                    if (allocated(error)) return
                    e(k) = abs(res%final_disp - ref%final_disp)
                end do
                call check(error, e(2) < 0.75_dp * e(1) .and. e(3) < 0.75_dp * e(2), &
                           'SLAMMER error decreases with dt')
                if (allocated(error)) return
                ratio = e(1) / e(3)
                call check(error, ratio > 4.0_dp, 'SLAMMER converges at least at first order')
                if (allocated(error)) return
                call check(error, e(3) < 1.0e-4_dp * ref%max_disp, 'SLAMMER close at dt/32')
                if (allocated(error)) return
            else
                do k = 1, 2
                    m = 8 * 32**(k - 1)
                    b = linear_upsample(a, m)
                    call run(error, b, dt / m, blk_of(mode, 0.08_dp), NEWMARK_SLAMMER, g0, &
                             res, 'slammer fine')
                    if (allocated(error)) return
                    e(k) = abs(res%final_disp - ref%final_disp)
                end do
                call check(error, e(2) < 0.1_dp * e(1) .and. e(2) < 5.0e-4_dp * ref%max_disp, &
                           'SLAMMER two ways: close at dt/256')
                if (allocated(error)) return
            end if
        end do
    end subroutine test_upsampling

    !> Full-cycle exponential pulse (A_g = 1 g, t_d = 1 s, g = 1: u in A_g t_d^2) sampled
    !> at t_d/N: the peak and residual slips of mode 'both' and the peak of mode 'down'
    !> under one lobe converge to the closed forms of seispulse_sliding_closed at second order.
    subroutine test_exp_convergence(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: betas(3) = [-pi, 0.4_dp, 2.0_dp], etas(2) = [0.3_dp, 0.55_dp]
        integer :: ns(3) = [64, 128, 256]
        real(dp) :: e_full(3), e_half(3), r
        real(dp), allocatable :: tau(:), a(:), v(:), d(:)
        type(full_cycle_t) :: fc
        type(half_cycle_t) :: hc
        type(newmark_result_t) :: res
        integer :: ib, ie, k, n, i, stat
        character(len=60) :: label
        do ib = 1, size(betas)
            do ie = 1, size(etas)
                write(label, '(a, f6.3, a, f5.2)') 'beta ', betas(ib), ' eta ', etas(ie)
                call full_cycle(etas(ie), etas(ie), betas(ib), 1.0_dp, .false., fc, stat)
                call half_cycle(etas(ie), betas(ib), 1.0_dp, hc, stat)
                do k = 1, size(ns)
                    n = 2 * ns(k) + 1
                    allocate(tau(n), a(n), v(n), d(n))
                    tau = [(real(i - 1, dp) / ns(k), i = 1, n)]
                    call exp_pulse(tau, [betas(ib)], .true., a, v, d, stat)
                    call run(error, a, 1.0_dp / ns(k), blk_of(NEWMARK_BOTH, etas(ie)), &
                             NEWMARK_EXACT, 1.0_dp, res, trim(label))
                    if (allocated(error)) return
                    e_full(k) = abs(res%final_disp - fc%ures) + abs(res%u_max - fc%um1)
                    ! one lobe: the half-cycle pulse
                    call exp_pulse(tau(1:ns(k) + 1), [betas(ib)], .false., a(1:ns(k) + 1), &
                                   v(1:ns(k) + 1), d(1:ns(k) + 1), stat)
                    call run(error, a(1:ns(k) + 1), 1.0_dp / ns(k), blk_of(NEWMARK_DOWN, &
                             etas(ie)), NEWMARK_EXACT, 1.0_dp, res, trim(label))
                    if (allocated(error)) return
                    e_half(k) = abs(res%max_disp - hc%um)
                    deallocate(tau, a, v, d)
                end do
                do k = 1, 2
                    r = e_full(k) / e_full(k + 1)
                    call check(error, r > 3.3_dp .and. r < 4.7_dp, trim(label) &
                               //': full cycle, error ratio at halved dt ~ 4')
                    if (allocated(error)) return
                    r = e_half(k) / e_half(k + 1)
                    call check(error, r > 3.3_dp .and. r < 4.7_dp, trim(label) &
                               //': half cycle, error ratio at halved dt ~ 4')
                    if (allocated(error)) return
                end do
                ! at second order, t_d/256 leaves up to ~2e-4 of the slip (the ratios above
                ! are the real check; this only rules out converging to a wrong value)
                call check(error, e_full(3) < 1.0e-3_dp * max(abs(fc%ures), fc%um1), &
                           trim(label)//': full cycle close at N = 256')
                if (allocated(error)) return
            end do
        end do
    end subroutine test_exp_convergence

    !> SLAMMER's loop under a constant a > ky over N samples (from rest, y_0 = 0): with
    !> y = (a - ky) 980.665, v_k = y dt (k - 1/2) and u_N = y dt^2 (1/4 + N (N - 1)/2) cm;
    !> the exact rule (first sample at t = 0, then the run-out after the record) gives
    !> y (N - 1)^2 dt^2 / 2 (a/ky) in consistent units.
    subroutine test_slammer_constant(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 50
        real(dp), parameter :: dt = 0.01_dp, a = 0.3_dp, ky = 0.1_dp
        real(dp) :: acc(n), uh(n), wh(n), y, expected
        type(newmark_result_t) :: res
        integer :: k
        acc = a
        y = (a - ky) * 100.0_dp * g0
        call run(error, acc, dt, blk_of(NEWMARK_DOWN, ky), NEWMARK_SLAMMER, g0, res, 'slammer', &
                 uh, wh)
        if (allocated(error)) return
        expected = y * dt**2 * (0.25_dp + n * (n - 1) / 2.0_dp) / 100.0_dp
        call check(error, res%final_disp, expected, rtol=1.0e-13_dp, message='u_N')
        if (allocated(error)) return
        do k = 1, n
            call check(error, wh(k), y * dt * (k - 0.5_dp) / 100.0_dp, rtol=1.0e-13_dp, &
                       message='v_k')
            if (allocated(error)) return
        end do
        call check(error, res%max_disp, expected, rtol=1.0e-13_dp, message='max')
        if (allocated(error)) return
        ! exact: (a - ky) g t^2/2 to t = (N-1) dt, then decelerating at ky g from
        ! v = (a - ky) g (N-1) dt: a further v^2/(2 ky g)
        call run(error, acc, dt, blk_of(NEWMARK_DOWN, ky), NEWMARK_EXACT, g0, res, 'exact')
        if (allocated(error)) return
        expected = 0.5_dp * (a - ky) * g0 * ((n - 1) * dt)**2 * (1.0_dp + (a - ky) / ky)
        call check(error, res%final_disp, expected, rtol=1.0e-13_dp, message='exact u')
        if (allocated(error)) return
        call check(error, res%t_end, (n - 1) * dt * (1.0_dp + (a - ky) / ky), rtol=1.0e-13_dp, &
                   message='exact stop time')
    end subroutine test_slammer_constant

    subroutine test_symmetry(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1500
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n), uh(n), wh(n)
        type(newmark_result_t) :: r1, r2
        integer :: method
        a = synthetic(n, dt, 3)
        do method = NEWMARK_EXACT, NEWMARK_SLAMMER
            call run(error, a, dt, blk_of(NEWMARK_BOTH, 0.05_dp), method, g0, r1, 'normal')
            if (allocated(error)) return
            call run(error, -a, dt, blk_of(NEWMARK_BOTH, 0.05_dp), method, g0, r2, 'inverse')
            if (allocated(error)) return
            call check(error, r2%final_disp, -r1%final_disp, rtol=1.0e-14_dp, &
                       message='inverted final')
            if (allocated(error)) return
            call check(error, r2%u_max, -r1%u_min, rtol=1.0e-14_dp, message='inverted extremes')
            if (allocated(error)) return
            call check(error, r1%u_min < 0.0_dp .and. r1%u_max > 0.0_dp, 'slides both ways')
            if (allocated(error)) return
            call run(error, a, dt, blk_of(NEWMARK_DOWN, 0.05_dp), method, g0, r1, 'one way', uh, wh)
            if (allocated(error)) return
            call check(error, minval(uh) >= 0.0_dp .and. minval(wh) >= 0.0_dp, &
                       'one way: u, u'' >= 0')
            if (allocated(error)) return
            call check(error, all(uh(2:) >= uh(:n - 1)), 'one way: u never decreases')
            if (allocated(error)) return
            call check(error, r1%u_min, 0.0_dp, message='one way: u_min')
            if (allocated(error)) return
        end do
    end subroutine test_symmetry

    !> newmark_incline is Eq. 1.31 with A_g = 1 g; with the factors K each slide's slip
    !> is K times that of the yield problem (K = 1).
    subroutine test_incline(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 1500
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n), eta1, eta2, k1, k2, expected
        type(newmark_block_t) :: b, b1
        type(newmark_result_t) :: rk, r1
        integer :: stat, j, method
        a = 2.0_dp * synthetic(n, dt, 1)
        call newmark_incline(0.45_dp, 12.0_dp, 5.0_dp, .true., b, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'incline')
        if (allocated(error)) return
        call inclined_resistances(0.45_dp, 1.0_dp, 12.0_dp, 5.0_dp, eta1, eta2, k1, k2, stat)
        call check(error, b%ky, eta1, message='ky')
        if (allocated(error)) return
        call check(error, b%ky_up, eta2, message='ky_up')
        if (allocated(error)) return
        ! Eq. 1.31 written out: eta_1,2 = mu cos(l)/cos(l-xi) (1 -+ tan(l)/mu)/(1 +- mu tan(l-xi))
        call check(error, b%ky, 0.45_dp * cos(12.0_dp * pi / 180) / cos(7.0_dp * pi / 180) &
                   * (1.0_dp - tan(12.0_dp * pi / 180) / 0.45_dp) &
                   / (1.0_dp + 0.45_dp * tan(7.0_dp * pi / 180)), rtol=1.0e-14_dp, message='1.31 down')
        if (allocated(error)) return
        call check(error, b%k_down, cos(7.0_dp * pi / 180) + 0.45_dp * sin(7.0_dp * pi / 180), &
                   rtol=1.0e-14_dp, message='K1')
        if (allocated(error)) return
        call check(error, b%k_up, k2, message='K2')
        if (allocated(error)) return
        b1 = b
        b1%k_down = 1.0_dp
        b1%k_up = 1.0_dp
        do method = NEWMARK_EXACT, NEWMARK_SLAMMER
            call run(error, a, dt, b, method, g0, rk, 'with K')
            if (allocated(error)) return
            call run(error, a, dt, b1, method, g0, r1, 'K = 1')
            if (allocated(error)) return
            call check(error, size(rk%slides), size(r1%slides), 'same slides')
            if (allocated(error)) return
            call check(error, count(r1%slides%direction < 0) > 0, 'slides uphill too')
            if (allocated(error)) return
            expected = 0.0_dp
            do j = 1, size(r1%slides)
                if (r1%slides(j)%direction > 0) then
                    expected = expected + b%k_down * (r1%slides(j)%u_stop - r1%slides(j)%u_start)
                else
                    expected = expected + b%k_up * (r1%slides(j)%u_stop - r1%slides(j)%u_start)
                end if
            end do
            call check(error, rk%final_disp, expected, rtol=1.0e-12_dp, message='sum of K slips')
            if (allocated(error)) return
        end do
        ! steeper than the friction angle: statically unstable
        call newmark_incline(0.3_dp, 20.0_dp, 0.0_dp, .true., b, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'unstable slope')
    end subroutine test_incline

    subroutine test_histories(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 2000
        real(dp), parameter :: dt = 0.01_dp
        real(dp) :: a(n), uh(n), wh(n)
        type(newmark_result_t) :: res
        integer :: method, j, i
        a = synthetic(n, dt, 1)
        do method = NEWMARK_EXACT, NEWMARK_SLAMMER
            call run(error, a, dt, blk_of(NEWMARK_BOTH, 0.06_dp), method, g0, res, 'hist', uh, wh)
            if (allocated(error)) return
            call check(error, res%t_end < (n - 1) * dt, 'at rest before the end')
            if (allocated(error)) return
            call check(error, uh(n), res%final_disp, rtol=1.0e-14_dp, message='u(end) = final')
            if (allocated(error)) return
            ! the extremes are at the stops: between samples for the exact rule
            call check(error, res%u_max, max(0.0_dp, maxval(res%slides%u_stop)), &
                       rtol=1.0e-14_dp, message='u_max')
            if (allocated(error)) return
            call check(error, res%u_min, min(0.0_dp, minval(res%slides%u_stop)), &
                       rtol=1.0e-14_dp, message='u_min')
            if (allocated(error)) return
            call check(error, maxval(uh) <= res%u_max .and. minval(uh) >= res%u_min, &
                       'the samples lie between the extremes')
            if (allocated(error)) return
            if (method == NEWMARK_SLAMMER) then
                call check(error, maxval(uh), res%u_max, rtol=1.0e-14_dp, message='u_max')
                if (allocated(error)) return
            end if
            ! (SLAMMER's rest is |v| < 1e-15 cm/s: a - (a/ky) ky leaves rounding)
            call check(error, wh(n), 0.0_dp, atol=1.0e-17_dp, message='at rest at the end')
            if (allocated(error)) return
            call check(error, maxval(abs(wh)) <= res%max_vel * (1.0_dp + 1.0e-14_dp), &
                       'max_vel bounds the history')
            if (allocated(error)) return
            ! samples strictly between slides are at rest
            do j = 1, size(res%slides) - 1
                do i = 1, n
                    if ((i - 1) * dt > res%slides(j)%t_stop + 1.0e-9_dp .and. &
                        (i - 1) * dt < res%slides(j + 1)%t_start - 1.0e-9_dp) then
                        call check(error, wh(i), 0.0_dp, atol=1.0e-17_dp, &
                                   message='at rest between slides')
                        if (allocated(error)) return
                        call check(error, uh(i), res%slides(j)%u_stop, rtol=1.0e-14_dp, &
                                   message='u between slides')
                        if (allocated(error)) return
                    end if
                end do
            end do
        end do
    end subroutine test_histories

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a(10), uh(9), nan
        type(newmark_result_t) :: res
        integer :: stat
        character(len=200) :: msg
        nan = ieee_value(nan, ieee_quiet_nan)
        a = 0.1_dp
        call expect(blk_of(NEWMARK_DOWN, 0.0_dp), a, 0.01_dp, NEWMARK_EXACT, 'ky = 0')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_DOWN, nan), a, 0.01_dp, NEWMARK_EXACT, 'ky = NaN')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_ASYM, 0.1_dp, ky_up=-1.0_dp), a, 0.01_dp, NEWMARK_EXACT, &
                    'ky_up = -1')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_ASYM, 0.1_dp, k_up=0.0_dp), a, 0.01_dp, NEWMARK_EXACT, 'k_up = 0')
        if (allocated(error)) return
        call expect(blk_of(7, 0.1_dp), a, 0.01_dp, NEWMARK_EXACT, 'mode')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_DOWN, 0.1_dp), a, 0.0_dp, NEWMARK_EXACT, 'dt = 0')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_DOWN, 0.1_dp), a, 0.01_dp, 3, 'method')
        if (allocated(error)) return
        a(4) = nan
        call expect(blk_of(NEWMARK_DOWN, 0.1_dp), a, 0.01_dp, NEWMARK_EXACT, 'accel(4) = NaN')
        if (allocated(error)) return
        call expect(blk_of(NEWMARK_DOWN, 0.1_dp), a(1:0), 0.01_dp, NEWMARK_EXACT, 'accel')
        if (allocated(error)) return
        a = 0.1_dp
        msg = ''
        call newmark_rigid(a, 0.01_dp, blk_of(NEWMARK_DOWN, 0.1_dp), NEWMARK_EXACT, g0, res, &
                           stat, msg, u_hist=uh)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'u_hist size')
        if (allocated(error)) return
        call check(error, index(msg, 'u_hist') == 1, 'message names u_hist: '//trim(msg))
        if (allocated(error)) return
        call newmark_rigid(a, 0.01_dp, blk_of(NEWMARK_DOWN, 0.1_dp), NEWMARK_EXACT, -1.0_dp, res, &
                           stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'g < 0')
    contains
        subroutine expect(b, acc, step, method, name)
            type(newmark_block_t), intent(in) :: b
            real(dp), intent(in) :: acc(:), step
            integer, intent(in) :: method
            character(len=*), intent(in) :: name
            character(len=:), allocatable :: key
            msg = ''
            call newmark_rigid(acc, step, b, method, g0, res, stat, msg)
            call check(error, stat, SEISPULSE_INVALID_INPUT, name//': status')
            if (allocated(error)) return
            key = name(1:scan(name // ' ', ' =') - 1)
            call check(error, index(msg, key) == 1, name//': message names '//key//': '//trim(msg))
        end subroutine expect
    end subroutine test_bad_input

end module test_newmark
