!> Rocking with rolling of a cylinder (seispulse_cylinder_roll): the planar limit against
!> rocking_sim, energy in free motion, the free-rocking scenarios of [AD11] section 1.2
!> with a geometry of our choice (r = 1 m, h = 3 m), the floor rule, bad input.
module test_cylinder_roll
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_special, only: pi
    use seispulse_pulses, only: pulse_t, sine_cycle_pulse, half_sine_pulse
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, symmetric_block, rock_pulse, &
                                     rock_record
    use seispulse_cylinder, only: rocking_body_t, cylinder_props
    use seispulse_cylinder_roll, only: cylinder_roll, roll_run_t, roll_output_name, ROLL_NOUT, &
                                       ROLL_OUT_THETA, ROLL_OUT_PSI, ROLL_OUT_ENERGY, &
                                       ROLL_OUT_THETA_RATE, ROLL_OUT_PSI_RATE, ROLL_OUT_NORMAL, &
                                       ROLL_OUT_FRICTION, ROLL_OUT_XG, ROLL_OUT_YG, &
                                       ROLL_OUT_XP, ROLL_OUT_YP, ROLL_OUT_SPIN, ROLL_RUN_REST, &
                                       ROLL_RUN_OVERTURN, ROLL_RUN_TIME_LIMIT, ROLL_RUN_NO_UPLIFT
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_cylinder_roll

    real(dp), parameter :: grav = 9.80665_dp

contains

    subroutine collect_cylinder_roll(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('planar limit = rock_pulse (impacts, rest)', test_planar_pulse), &
                 new_unittest('planar limit = rock_record (two components)', &
                              test_planar_record), &
                 new_unittest('free motion with spin conserves energy', test_energy), &
                 new_unittest('free rocking theta0 = 0.2 with spin 0, 0.01, 0.1', &
                              test_scenarios), &
                 new_unittest('statics at rest: N = m g, |F_t|/N = |a_g|/g', test_rest_forces), &
                 new_unittest('steady forces: N and friction from the planar closed form', &
                              test_planar_forces), &
                 new_unittest('overturning at theta = pi/2', test_overturn), &
                 new_unittest('bad input names the parameter', test_bad_input), &
                 new_unittest('output column names', test_names), &
                 new_unittest('small spin: floor passes end at rest, quickly', test_floor_rest), &
                 new_unittest('the body pose is continuous across impacts and floor passes', &
                              test_pose_continuous), &
                 new_unittest('e = 1, t_max = inf: integrated to the last output time', &
                              test_elastic_open_end)]
    end subroutine collect_cylinder_roll

    !> Solid cylinder, radius r, CoM height h (half the height), mass m (cylinder_props),
    !> its inertias checked against the closed forms.
    function solid(r, h, m) result(b)
        real(dp), intent(in) :: r, h, m
        type(rocking_body_t) :: b
        integer :: stat
        call cylinder_props(r, h, m, grav, b, stat)
        if (stat /= SEISPULSE_SUCCESS .or. abs(b%j_g - m * (3.0_dp * r**2 + 4.0_dp * h**2) &
                / 12.0_dp) > 1.0e-12_dp * b%j_g .or. abs(b%j_axis - 0.5_dp * m * r**2) &
                > 1.0e-12_dp * b%j_axis) error stop 'cylinder_props'
    end function solid

    subroutine grid(t_end, n, t)
        real(dp), intent(in) :: t_end
        integer, intent(in) :: n
        real(dp), allocatable, intent(out) :: t(:)
        integer :: i
        allocate(t(n))
        do i = 1, n
            t(i) = t_end * real(i - 1, dp) / real(n - 1, dp)
        end do
    end subroutine grid

    !> Zero spin and heading rate: theta = |theta| of the planar model with
    !> J_o = j_g + m R^2 (symmetric_block), impacts included, under a pulse in a fixed
    !> direction (30 degrees). Both from rest; e = Housner's.
    subroutine test_planar_pulse(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: prun
        type(roll_run_t) :: run
        type(pulse_t) :: pl
        real(dp), allocatable :: t(:), th(:), om(:), hist(:, :)
        integer :: stat
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        call symmetric_block(b%big_r, b%theta_c, b%j_o / (b%mass * b%big_r**2), grav, blk, stat)
        call check(error, stat == SEISPULSE_SUCCESS, 'symmetric_block')
        if (allocated(error)) return
        pl = sine_cycle_pulse(0.6_dp * grav, 1.0_dp)
        call grid(12.0_dp, 601, t)
        allocate(th(size(t)), om(size(t)), hist(ROLL_NOUT, size(t)))
        call rock_pulse(blk, pl, prun, stat, msg, t, th, om, t_max=12.0_dp, rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'rock_pulse: '//trim(msg))
        if (allocated(error)) return
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, pulse=pl, direction=pi / 6.0_dp, &
                           t_max=12.0_dp, rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
        if (allocated(error)) return
        call check(error, prun%n_impacts >= 3, 'the case has impacts')
        if (allocated(error)) return
        call check(error, run%n_impacts, prun%n_impacts, 'impacts')
        if (allocated(error)) return
        call check(error, run%n_floor, 0, 'no floor passes without spin')
        if (allocated(error)) return
        call check(error, run%t_impacts, prun%t_impacts(1:prun%n_impacts), atol=1.0e-9_dp, &
                   rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_THETA, :), abs(th), atol=1.0e-9_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, run%t_uplift, prun%t_uplift, atol=1.0e-12_dp, rtol=0.0_dp)
        if (allocated(error)) return
        ! the heading: the rocking plane is the pulse's (lean away from the first push), and
        ! the heading rate stays 0
        call check(error, maxval(abs(hist(ROLL_OUT_PSI_RATE, :))) < 1.0e-9_dp, 'psi rate 0')
        if (allocated(error)) return
        ! the centre of mass moves along the direction of the pulse only
        call check(error, maxval(abs(-sin(pi / 6) * hist(ROLL_OUT_XG, :) &
                                     + cos(pi / 6) * hist(ROLL_OUT_YG, :))) < 1.0e-12_dp, &
                   'G stays in the rocking plane')
    end subroutine test_planar_pulse

    !> The same through the record path: a sampled half-sine along (cos 1, sin 1) as two
    !> components, against rock_record of the projected samples.
    subroutine test_planar_record(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(rocking_block_t) :: blk
        type(rocking_run_t) :: prun
        type(roll_run_t) :: run
        real(dp), allocatable :: t(:), th(:), om(:), hist(:, :), a(:)
        real(dp) :: dt
        integer :: stat, i, n
        character(len=200) :: msg
        b = solid(0.5_dp, 2.0_dp, 10.0_dp)
        call symmetric_block(b%big_r, b%theta_c, b%j_o / (b%mass * b%big_r**2), grav, blk, stat)
        dt = 0.01_dp
        n = 81
        allocate(a(n))
        do i = 1, n
            a(i) = 0.45_dp * sin(pi * real(i - 1, dp) / real(n - 1, dp))
        end do
        call grid(6.0_dp, 301, t)
        allocate(th(size(t)), om(size(t)), hist(ROLL_NOUT, size(t)))
        call rock_record(blk, a, dt, grav, prun, stat, msg, t, th, om, t_max=6.0_dp, &
                         rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'rock_record: '//trim(msg))
        if (allocated(error)) return
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, accel_x=a * cos(1.0_dp), &
                           accel_y=a * sin(1.0_dp), dt=dt, g_rec=grav, t_max=6.0_dp, &
                           rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
        if (allocated(error)) return
        call check(error, prun%n_impacts >= 1, 'the case has impacts')
        if (allocated(error)) return
        call check(error, run%n_impacts, prun%n_impacts, 'impacts')
        if (allocated(error)) return
        call check(error, run%t_impacts, prun%t_impacts(1:prun%n_impacts), atol=1.0e-9_dp, &
                   rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_THETA, :), abs(th), atol=1.0e-9_dp, rtol=0.0_dp)
    end subroutine test_planar_record

    !> Free motion from a tilt with heading rate and spin: E constant to 1e-9 of the energy
    !> above rest E - m g h between impacts (the run's drift), and on the output grid.
    subroutine test_energy(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        real(dp), allocatable :: t(:), hist(:, :)
        integer :: stat
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 500.0_dp)
        call grid(1.5_dp, 151, t)
        allocate(hist(ROLL_NOUT, size(t)))
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.2_dp, psi0=0.3_dp, &
                           theta_rate0=0.05_dp, psi_rate0=0.4_dp, spin_rate0=1.5_dp, &
                           rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
        if (allocated(error)) return
        call check(error, run%n_impacts, 0, 'no impact in this window')
        if (allocated(error)) return
        call check(error, run%energy_drift < 1.0e-9_dp, 'drift '//trim(num(run%energy_drift)))
        if (allocated(error)) return
        ! on the grid too, relative to the energy above rest (b%h is the height of G at rest)
        call check(error, hist(ROLL_OUT_ENERGY, :), spread(hist(ROLL_OUT_ENERGY, 1), 1, size(t)), &
                   rtol=0.0_dp, atol=1.0e-9_dp * (hist(ROLL_OUT_ENERGY, 1) - b%mass * grav * b%h))
        if (allocated(error)) return
        ! the heading does turn
        call check(error, abs(hist(ROLL_OUT_PSI, size(t)) - 0.3_dp) > 0.1_dp, 'psi moves')
    end subroutine test_energy

    !> [AD11]'s free-rocking runs (theta0 = 0.2 rad; spin rates 0, 0.01, 0.1 rad/s; our
    !> geometry r = 1 m, h = 3 m): theta(t) nearly the same over the first half-cycle; psi
    !> jumps by pi at the zero-spin impact, and passes through intermediate values with spin.
    subroutine test_scenarios(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run(3)
        real(dp), allocatable :: t(:), hist(:, :, :)
        real(dp) :: spin(3), t_half, dpsi
        integer :: stat, k, i, i_half
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        spin = [0.0_dp, 0.01_dp, 0.1_dp]
        call grid(4.0_dp, 4001, t)
        allocate(hist(ROLL_NOUT, size(t), 3))
        do k = 1, 3
            msg = ''
            call cylinder_roll(b, t, hist(:, :, k), run(k), stat, msg, theta0=0.2_dp, &
                               spin_rate0=spin(k), rtol=1.0e-11_dp)
            call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
            if (allocated(error)) return
        end do
        call check(error, run(1)%n_impacts >= 1, 'zero spin: an impact')
        if (allocated(error)) return
        t_half = run(1)%t_impacts(1)
        i_half = int(t_half / (t(2) - t(1)))
        do k = 2, 3
            call check(error, hist(ROLL_OUT_THETA, 1:i_half, k), hist(ROLL_OUT_THETA, 1:i_half, 1), &
                       atol=0.02_dp * 0.2_dp, rtol=0.0_dp)
            if (allocated(error)) return
        end do
        ! zero spin: psi = 0 before, pi after the first impact, nothing in between
        call check(error, all(abs(hist(ROLL_OUT_PSI, 1:i_half, 1)) < 1.0e-12_dp), 'psi 0')
        if (allocated(error)) return
        call check(error, abs(hist(ROLL_OUT_PSI, i_half + 2, 1) - pi) < 1.0e-12_dp, 'psi pi')
        if (allocated(error)) return
        ! spin 0.1: psi passes through values between 0.05 pi and 0.95 pi (mod pi) near
        ! the first approach to theta = 0, on the output grid (continuous motion)
        dpsi = 0.0_dp
        do i = 1, size(t)
            if (t(i) > t_half + 0.5_dp) exit
            dpsi = max(dpsi, min(modulo(hist(ROLL_OUT_PSI, i, 3), pi), &
                                 pi - modulo(hist(ROLL_OUT_PSI, i, 3), pi)))
        end do
        call check(error, dpsi > 0.05_dp * pi, 'spin 0.1: intermediate heading values, max ' &
                   //trim(num(dpsi)))
        if (allocated(error)) return
        ! energy is lost only at impacts: with spin 0.1 nothing beyond the drift
        call check(error, run(3)%energy_drift < 1.0e-8_dp, 'drift')
    end subroutine test_scenarios

    !> At rest under a pulse below the uplift threshold: N = m g and |F_t|/N = |a_g|/g.
    subroutine test_rest_forces(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        type(pulse_t) :: pl
        real(dp) :: t(3), hist(ROLL_NOUT, 3)
        integer :: stat
        b = solid(1.0_dp, 3.0_dp, 7.0_dp)
        pl = half_sine_pulse(0.2_dp * grav, 1.0_dp)
        t = [0.1_dp, 0.5_dp, 2.0_dp]
        call cylinder_roll(b, t, hist, run, stat, pulse=pl, direction=1.0_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, run%outcome, ROLL_RUN_NO_UPLIFT, 'no uplift')
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_NORMAL, :), spread(7.0_dp * grav, 1, 3), rtol=1.0e-14_dp)
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_FRICTION, :), 0.2_dp * abs(sin(pi * [0.1_dp, 0.5_dp, &
                   0.0_dp])), rtol=1.0e-13_dp, atol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_ENERGY, 1), 7.0_dp * grav * 3.0_dp, rtol=1.0e-14_dp)
    end subroutine test_rest_forces

    !> Planar free rocking: the contact force from Newton's law for G on the circle about
    !> the pivot, from theta, theta' and theta'' of the planar equation (closed form here):
    !> G = P + R (sin(phi), cos(phi)) in the rocking plane (horizontal along -d, vertical),
    !> phi = theta_c - theta... we use the normal force N = m (g + z_G''), z_G = R cos(theta_c
    !> - theta): z_G'' = R (sin(a) theta'' - cos(a) theta'^2), a = theta_c - theta.
    subroutine test_planar_forces(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        real(dp), allocatable :: t(:), hist(:, :)
        real(dp) :: th, w, al, thdd, zdd, xdd, nref, fref
        integer :: stat, i
        b = solid(0.8_dp, 2.5_dp, 3.0_dp)
        call grid(0.8_dp, 9, t)
        allocate(hist(ROLL_NOUT, size(t)))
        call cylinder_roll(b, t, hist, run, stat, theta0=0.1_dp, theta_rate0=0.2_dp, &
                           rtol=1.0e-12_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        do i = 1, size(t)
            th = hist(ROLL_OUT_THETA, i)
            w = hist(ROLL_OUT_THETA_RATE, i)
            al = b%theta_c - th
            thdd = -b%p**2 * sin(al)
            ! z_G = R cos(al), horizontal x_G = R sin(al) from the pivot (towards the body)
            zdd = b%big_r * (sin(al) * thdd - cos(al) * w**2)
            xdd = b%big_r * (-cos(al) * thdd - sin(al) * w**2)
            nref = b%mass * (grav + zdd)
            fref = abs(b%mass * xdd) / nref
            call check(error, hist(ROLL_OUT_NORMAL, i), nref, rtol=1.0e-9_dp)
            if (allocated(error)) return
            call check(error, hist(ROLL_OUT_FRICTION, i), fref, rtol=1.0e-8_dp, atol=1.0e-12_dp)
            if (allocated(error)) return
        end do
        ! the contact point is the rim point under the lean: horizontally
        ! r cos(theta) - h sin(theta) from G (the horizontal part of rho, (L.1)), G at (0, 0)
        call check(error, hypot(hist(ROLL_OUT_XP, 1), hist(ROLL_OUT_YP, 1)), &
                   b%r * cos(0.1_dp) - b%h * sin(0.1_dp), rtol=1.0e-13_dp)
    end subroutine test_planar_forces

    !> A strong pulse overturns the body; the history ends on its side.
    subroutine test_overturn(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        real(dp), allocatable :: t(:), hist(:, :)
        integer :: stat
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        call grid(10.0_dp, 101, t)
        allocate(hist(ROLL_NOUT, size(t)))
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, pulse=sine_cycle_pulse(0.8_dp * grav, &
                           1.0_dp), theta_rate0=0.0_dp)
        call check(error, stat == SEISPULSE_SUCCESS, 'status: '//trim(msg))
        if (allocated(error)) return
        call check(error, run%outcome, ROLL_RUN_OVERTURN, 'overturns')
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_THETA, size(t)), pi / 2, rtol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, ieee_is_nan(hist(ROLL_OUT_NORMAL, size(t))), 'no contact force after')
    end subroutine test_overturn

    subroutine test_bad_input(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        real(dp) :: t(2), hist(ROLL_NOUT, 2), nan
        integer :: stat
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1.0_dp)
        t = [0.0_dp, 1.0_dp]
        nan = ieee_value(nan, ieee_quiet_nan)
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=-0.1_dp)
        call expect(error, stat, msg, 'theta0')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=pi / 2)
        call expect(error, stat, msg, 'theta0')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp, spin_rate0=nan)
        call expect(error, stat, msg, 'spin_rate0')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp, psi_rate0=nan)
        call expect(error, stat, msg, 'psi_rate0')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp, e=1.5_dp)
        call expect(error, stat, msg, 'e = ')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, accel_x=[0.1_dp, 0.2_dp], &
                           accel_y=[0.1_dp, 0.2_dp], dt=0.0_dp)
        call expect(error, stat, msg, 'dt')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, accel_x=[0.1_dp, 0.2_dp], &
                           accel_y=[0.1_dp], dt=0.01_dp)
        call expect(error, stat, msg, 'accel_y')
        if (allocated(error)) return
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp, rtol=0.0_dp)
        call expect(error, stat, msg, 'rtol')
        if (allocated(error)) return
        b%j_axis = nan
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp)
        call expect(error, stat, msg, 'j_axis')
    end subroutine test_bad_input

    subroutine expect(error, stat, msg, name)
        type(test_error), allocatable, intent(out) :: error
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg, name
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, name) > 0, &
                   'expected an error naming '//name//', got: '//trim(msg))
    end subroutine expect

    subroutine test_names(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: k
        do k = 1, ROLL_NOUT
            call check(error, len(roll_output_name(k)) > 0, 'column name')
            if (allocated(error)) return
        end do
        call check(error, roll_output_name(ROLL_OUT_THETA) == 'theta', 'theta')
        if (allocated(error)) return
        call check(error, len(roll_output_name(ROLL_NOUT + 1)) == 0, 'beyond the table')
    end subroutine test_names

    !> A free run from theta0 = 0.2 rad with a spin rate of 1e-5 rad/s: the floor passes
    !> damp theta' (restitution) until the rocking left is negligible, then rest; it must
    !> not wobble at theta ~ theta_floor until the step budget (doc/rolling.md section 4).
    subroutine test_floor_rest(error)
        type(test_error), allocatable, intent(out) :: error
        type(roll_run_t) :: run
        real(dp) :: t(2) = [0.0_dp, 4.0_dp], hist(ROLL_NOUT, 2)
        character(len=200) :: msg = ''
        type(rocking_body_t) :: b
        integer :: stat
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.2_dp, spin_rate0=1.0e-5_dp, &
                           t_max=huge(1.0_dp))
        call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
        if (allocated(error)) return
        call check(error, run%outcome, ROLL_RUN_REST, 'outcome')
        if (allocated(error)) return
        call check(error, run%n_floor > 0 .and. run%n_floor == run%n_impacts, 'floor passes')
        if (allocated(error)) return
        ! planar: the Zeno sequence of e = Housner's from 0.2 rad ends near 8.7 s
        call check(error, run%t_end > 4.0_dp .and. run%t_end < 20.0_dp, &
                   't_end '//trim(num(run%t_end)))
        if (allocated(error)) return
        call check(error, run%n_steps < 50000, 'steps')
        if (allocated(error)) return
        ! the same run with the default t_max (the last output time) is still rocking there
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.2_dp, spin_rate0=1.0e-5_dp)
        call check(error, run%outcome, ROLL_RUN_TIME_LIMIT, 'outcome at t = 4 s')
    end subroutine test_floor_rest

    !> Rz(psi) Rx(theta) Rz(phi_s) (the body's rotation) from the output columns.
    pure function pose(col) result(rm)
        real(dp), intent(in) :: col(:)
        real(dp) :: rm(3, 3)
        real(dp) :: cz(3, 3), cx(3, 3), cs(3, 3)
        cz = rz(col(ROLL_OUT_PSI))
        cs = rz(col(ROLL_OUT_SPIN))
        cx = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, cos(col(ROLL_OUT_THETA)), &
                      sin(col(ROLL_OUT_THETA)), 0.0_dp, -sin(col(ROLL_OUT_THETA)), &
                      cos(col(ROLL_OUT_THETA))], [3, 3])
        rm = matmul(cz, matmul(cx, cs))
    end function pose

    pure function rz(a) result(rm)
        real(dp), intent(in) :: a
        real(dp) :: rm(3, 3)
        rm = reshape([cos(a), sin(a), 0.0_dp, -sin(a), cos(a), 0.0_dp, 0.0_dp, 0.0_dp, &
                      1.0_dp], [3, 3])
    end function rz

    !> Across an impact (zero spin, theta = 0) and a floor pass (spin 1e-5 rad/s, theta
    !> kept at theta_floor), output times 1e-7 s either side: the contact jumps to the
    !> opposite rim point (psi + pi), but the body's rotation matrix does not jump (the
    !> tilt changes by theta' 2e-7 s at an impact, by 2 theta_floor = 6.4e-6 rad at a
    !> floor pass), and psi + phi_s is continuous.
    subroutine test_pose_continuous(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run
        real(dp) :: t(2), hist(ROLL_NOUT, 2), t1(1), h1(ROLL_NOUT, 1), spin, tol
        integer :: stat, k
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        do k = 1, 2
            spin = 0.0_dp
            tol = 1.0e-6_dp
            if (k == 2) then
                spin = 1.0e-5_dp
                tol = 1.0e-5_dp
            end if
            msg = ''
            t1 = 2.0_dp
            call cylinder_roll(b, t1, h1, run, stat, msg, theta0=0.2_dp, psi0=0.4_dp, &
                               spin0=0.3_dp, spin_rate0=spin)
            call check(error, stat == SEISPULSE_SUCCESS .and. run%n_impacts > 0, &
                       'a first impact: '//trim(msg))
            if (allocated(error)) return
            call check(error, run%n_floor, k - 1, 'kind of the first impact')
            if (allocated(error)) return
            t = run%t_impacts(1) + [-1.0e-7_dp, 1.0e-7_dp]
            call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.2_dp, psi0=0.4_dp, &
                               spin0=0.3_dp, spin_rate0=spin)
            call check(error, stat == SEISPULSE_SUCCESS .and. run%n_impacts == 1, 'one impact')
            if (allocated(error)) return
            ! the contact point does jump (to the opposite rim point)
            call check(error, hypot(hist(ROLL_OUT_XP, 2) - hist(ROLL_OUT_XP, 1), &
                                    hist(ROLL_OUT_YP, 2) - hist(ROLL_OUT_YP, 1)) > 1.9_dp, &
                       'contact jumps')
            if (allocated(error)) return
            call check(error, maxval(abs(pose(hist(:, 2)) - pose(hist(:, 1)))) < tol, &
                       'pose jumps by '//trim(num(maxval(abs(pose(hist(:, 2)) &
                                                             - pose(hist(:, 1)))))))
            if (allocated(error)) return
            call check(error, abs(hist(ROLL_OUT_PSI, 2) + hist(ROLL_OUT_SPIN, 2) &
                                  - hist(ROLL_OUT_PSI, 1) - hist(ROLL_OUT_SPIN, 1)) < tol, &
                       'psi + phi_s continuous')
            if (allocated(error)) return
        end do
    end subroutine test_pose_continuous

    !> e = 1 and t_max = +inf: rocking never ends, but the output up to the last output time
    !> is computed (the same as with t_max = that time), the run ends there.
    subroutine test_elastic_open_end(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_body_t) :: b
        type(roll_run_t) :: run, ref
        real(dp) :: t(2), hist(ROLL_NOUT, 2), href(ROLL_NOUT, 2)
        integer :: stat
        character(len=200) :: msg
        b = solid(1.0_dp, 3.0_dp, 1000.0_dp)
        t = [0.0_dp, 3.0_dp]
        msg = ''
        call cylinder_roll(b, t, hist, run, stat, msg, theta0=0.1_dp, e=1.0_dp, &
                           t_max=huge(1.0_dp))
        call check(error, stat == SEISPULSE_SUCCESS, 'cylinder_roll: '//trim(msg))
        if (allocated(error)) return
        call cylinder_roll(b, t, href, ref, stat, msg, theta0=0.1_dp, e=1.0_dp, t_max=3.0_dp)
        call check(error, run%outcome, ROLL_RUN_TIME_LIMIT, 'outcome')
        if (allocated(error)) return
        call check(error, run%t_end, 3.0_dp, rtol=0.0_dp, atol=0.0_dp)
        if (allocated(error)) return
        call check(error, ref%n_impacts > 0 .and. run%n_impacts == ref%n_impacts, 'impacts')
        if (allocated(error)) return
        call check(error, hist(ROLL_OUT_THETA, :), href(ROLL_OUT_THETA, :), rtol=0.0_dp, &
                   atol=1.0e-12_dp)
    end subroutine test_elastic_open_end

    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=32) :: s
        write(s, '(es12.4)') x
    end function num

end module test_cylinder_roll
