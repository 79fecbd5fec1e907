!> Optional arguments with the defaults of the Python layer (seispulse_optval): every
!> routine called with them omitted gives bit for bit the call with the defaults written
!> out, and, where a closed form exists, that closed form evaluated here: Coulomb's
!> (1 - sin phi)/(1 + sin phi) for a smooth vertical wall with a level backfill at
!> kh = kv = 0, the dry thrust 1/2 gamma (1 - kv) K H^2, EN 1998-1's 2.5 ag plateau on
!> ground A at 5 % and 2.5 ag/1.5 for the design spectrum, kh = alpha S with kv = 0.5 kh,
!> and the resistances of a horizontal plane eta = mu/(A_g/g). A value other than the
!> default must change the answer (so that a default wired to the wrong argument fails).
module test_optional_args
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_optval, only: optval
    use seispulse_codes, only: mononobe_okabe, ec8_thrust_t, ec8_thrust, &
                               ec8_seismic_coefficients, ec8_vertical_ratio, &
                               ec8_elastic_spectrum, ec8_design_spectrum, WATER_DRY, &
                               EC8_SPECTRUM_TYPE_1, EC8_GROUND_A, EC8_GROUND_C
    use seispulse_sliding_closed, only: sliding_block_t, block_response, inclined_resistances
    use seispulse_newmark, only: newmark_block_t, newmark_incline
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_pulses, only: pulse_t, exponential_pulse, triangular_pulse, exp_pulse, &
                                exp_pulse_peaks
    use seispulse_sliding_closed, only: half_cycle_t, full_cycle_t, yield_time, half_cycle, &
                                        full_cycle
    use seispulse_sliding_norm, only: table_1_3
    use seispulse_rocking_sim, only: rocking_block_t, rectangular_block, symmetric_block
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props
    use seispulse_sdof_sim, only: sdof_response
    use seispulse_intensity, only: spectral_acceleration
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_optional_args

    real(dp), parameter :: pi = 3.141592653589793238462643383279502884_dp

contains

    subroutine collect_optional_args(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('optval: present value or default (real, integer, logical)', &
                              test_optval), &
                 new_unittest('mononobe_okabe: omitted = explicit defaults = Coulomb', &
                              test_mononobe_okabe), &
                 new_unittest('ec8_thrust: omitted = explicit defaults = 1/2 gamma K H^2', &
                              test_ec8_thrust), &
                 new_unittest('ec8_seismic_coefficients: r = 1, Type 1 ratio by default', &
                              test_seismic_coefficients), &
                 new_unittest('EC8 spectra: Type 1, ground A, 5 %, q 1.5, beta 0.2', &
                              test_spectra), &
                 new_unittest('block_response, inclined_resistances, newmark_incline', &
                              test_sliding), &
                 new_unittest('pulses: full = .false., peak_frac = 0.5', test_pulses), &
                 new_unittest('yield_time, half_cycle, full_cycle, table_1_3 defaults', &
                              test_sliding_closed), &
                 new_unittest('rocking blocks and bodies: g, mass defaults; p = sqrt(3g/4R)', &
                              test_bodies), &
                 new_unittest('sdof_response, spectral_acceleration: 5 %, standard g', &
                              test_oscillator)]
    end subroutine collect_optional_args

    subroutine test_optval(error)
        type(test_error), allocatable, intent(out) :: error
        call check(error, optval(2.5_dp, 1.0_dp), 2.5_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, absent_real(), 1.0_dp, rtol=0.0_dp)
        if (allocated(error)) return
        call check(error, optval(3, 7), 3)
        if (allocated(error)) return
        call check(error, absent_int(), 7)
        if (allocated(error)) return
        call check(error, optval(.false., .true.) .eqv. .false., 'logical present')
        if (allocated(error)) return
        call check(error, absent_logical() .eqv. .true., 'logical absent')
    contains
        real(dp) function absent_real(x)
            real(dp), intent(in), optional :: x
            absent_real = optval(x, 1.0_dp)
        end function absent_real
        integer function absent_int(x)
            integer, intent(in), optional :: x
            absent_int = optval(x, 7)
        end function absent_int
        logical function absent_logical(x)
            logical, intent(in), optional :: x
            absent_logical = optval(x, .true.)
        end function absent_logical
    end subroutine test_optval

    subroutine test_mononobe_okabe(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: k0, th0, k1, th1, k2, th2, s
        integer :: stat
        ! kh = kv = 0: Coulomb's active coefficient of a smooth vertical wall, level backfill
        call mononobe_okabe(30.0_dp, 0.0_dp, 0.0_dp, k=k0, theta=th0, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        s = sin(30.0_dp*pi/180.0_dp)
        call check(error, k0, (1.0_dp - s)/(1.0_dp + s), rtol=1.0e-14_dp, &
                   message='Coulomb K_a at phi = 30 deg')
        if (allocated(error)) return
        ! seismic case: omitted = explicit defaults, bit for bit
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, k=k1, theta=th1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, 0.0_dp, 90.0_dp, 0.0_dp, .false., &
                            1.0_dp, k2, th2, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, k1, k2, rtol=0.0_dp, message='K omitted vs explicit')
        if (allocated(error)) return
        call check(error, th1, th2, rtol=0.0_dp, message='theta omitted vs explicit')
        if (allocated(error)) return
        ! one optional given by keyword, the others omitted
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, passive=.true., k=k1, theta=th1, &
                            stat=stat)
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, 0.0_dp, 90.0_dp, 0.0_dp, .true., &
                            1.0_dp, k2, th2, stat)
        call check(error, k1, k2, rtol=0.0_dp, message='passive K omitted vs explicit')
        if (allocated(error)) return
        call check(error, k1 > 1.0_dp, 'passive K > 1')
        if (allocated(error)) return
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, k=k1, theta=th1, stat=stat)
        call mononobe_okabe(32.0_dp, 0.15_dp, -0.075_dp, gamma_phi=1.25_dp, k=k2, theta=th2, &
                            stat=stat)
        call check(error, k2 > 1.01_dp*k1, 'gamma_phi = 1.25 raises the active K')
    end subroutine test_mononobe_okabe

    subroutine test_ec8_thrust(error)
        type(test_error), allocatable, intent(out) :: error
        type(ec8_thrust_t) :: r1, r2
        real(dp) :: k, theta
        integer :: stat
        call ec8_thrust(6.0_dp, 20.0_dp, 30.0_dp, kh=0.1_dp, kv=0.05_dp, res=r1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call ec8_thrust(6.0_dp, 20.0_dp, 30.0_dp, 0.0_dp, 90.0_dp, 0.0_dp, 0.1_dp, 0.05_dp, &
                        WATER_DRY, 9.81_dp, 0.0_dp, 1.0_dp, r2, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, r1%total, r2%total, rtol=0.0_dp, message='total omitted vs explicit')
        if (allocated(error)) return
        call check(error, r1%m_base, r2%m_base, rtol=0.0_dp, message='moment')
        if (allocated(error)) return
        ! dry: E.1 with K of mononobe_okabe (same defaults), no water terms
        call mononobe_okabe(30.0_dp, 0.1_dp, 0.05_dp, k=k, theta=theta, stat=stat)
        call check(error, r1%total, 0.5_dp*20.0_dp*(1.0_dp - 0.05_dp)*k*36.0_dp, &
                   rtol=1.0e-14_dp, message='E.1 dry')
        if (allocated(error)) return
        call check(error, r1%e_ws + r1%e_wd, 0.0_dp, atol=0.0_dp, message='no water thrust')
        if (allocated(error)) return
        ! permeable soil needs gamma_d: omitted, the check names it
        call ec8_thrust(6.0_dp, 20.0_dp, 30.0_dp, kh=0.1_dp, kv=0.05_dp, water_case=3, &
                        res=r1, stat=stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'permeable without gamma_d')
    end subroutine test_ec8_thrust

    subroutine test_seismic_coefficients(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: kh1, kv1, kh2, kv2
        integer :: stat
        call ec8_seismic_coefficients(0.24_dp, 1.15_dp, kh=kh1, kv=kv1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.24_dp, 1.15_dp, 1.0_dp, &
                                      ec8_vertical_ratio(EC8_SPECTRUM_TYPE_1), kh2, kv2, stat)
        call check(error, kh1, kh2, rtol=0.0_dp, message='kh omitted vs explicit')
        if (allocated(error)) return
        call check(error, kv1, kv2, rtol=0.0_dp, message='kv omitted vs explicit')
        if (allocated(error)) return
        call check(error, kh1, 0.24_dp*1.15_dp, rtol=1.0e-15_dp, message='kh = alpha S (7.1)')
        if (allocated(error)) return
        call check(error, kv1, 0.5_dp*kh1, rtol=1.0e-15_dp, message='kv = 0.5 kh (7.2)')
        if (allocated(error)) return
        call ec8_seismic_coefficients(0.24_dp, 1.15_dp, r=2.0_dp, kh=kh2, kv=kv2, stat=stat)
        call check(error, kh2, 0.5_dp*kh1, rtol=1.0e-15_dp, message='r = 2 halves kh')
    end subroutine test_seismic_coefficients

    subroutine test_spectra(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp), parameter :: periods(5) = [0.0_dp, 0.1_dp, 0.3_dp, 1.0_dp, 5.0_dp]
        real(dp) :: s1(5), s2(5)
        integer :: stat, i
        call ec8_elastic_spectrum(periods, 2.0_dp, se=s1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call ec8_elastic_spectrum(periods, 2.0_dp, EC8_SPECTRUM_TYPE_1, EC8_GROUND_A, 5.0_dp, &
                                  s2, stat)
        do i = 1, 5
            call check(error, s1(i), s2(i), rtol=0.0_dp, message='Se omitted vs explicit')
            if (allocated(error)) return
        end do
        ! ground A (S = 1), 5 % (eta = 1): the plateau 2.5 ag at T = 0.3 s in [0.15, 0.4]
        call check(error, s1(3), 2.5_dp*2.0_dp, rtol=1.0e-15_dp, message='Se plateau')
        if (allocated(error)) return
        call ec8_elastic_spectrum(periods, 2.0_dp, ground=EC8_GROUND_C, se=s2, stat=stat)
        call check(error, s2(3) > s1(3), 'ground C raises the plateau')
        if (allocated(error)) return
        call ec8_design_spectrum(periods, 2.0_dp, sd=s1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call ec8_design_spectrum(periods, 2.0_dp, EC8_SPECTRUM_TYPE_1, EC8_GROUND_A, 1.5_dp, &
                                 0.2_dp, s2, stat)
        do i = 1, 5
            call check(error, s1(i), s2(i), rtol=0.0_dp, message='Sd omitted vs explicit')
            if (allocated(error)) return
        end do
        call check(error, s1(3), 2.0_dp*2.5_dp/1.5_dp, rtol=1.0e-15_dp, message='Sd plateau')
        if (allocated(error)) return
        ! at 5 s the floor 0.2 ag = 0.4 governs (2.5/1.5 ag 0.4 * 2/25 = 0.107 ag < 0.2 ag)
        call check(error, s1(5), 0.2_dp*2.0_dp, rtol=1.0e-15_dp, message='Sd floor')
    end subroutine test_spectra

    subroutine test_sliding(error)
        type(test_error), allocatable, intent(out) :: error
        type(sliding_block_t) :: b1, b2
        type(newmark_block_t) :: n1, n2
        real(dp) :: e1, e2, k1, k2, f1, f2, j1, j2
        integer :: stat
        call block_response(0.3_dp, 0.5_dp, 0.6_dp, -3.0_dp, res=b1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call block_response(0.3_dp, 0.5_dp, 0.6_dp, -3.0_dp, .false., 0.0_dp, 0.0_dp, 1.0_dp, &
                            .false., .true., STANDARD_GRAVITY, b2, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, b1%u_m1, b2%u_m1, rtol=0.0_dp, message='u_m1 omitted vs explicit')
        if (allocated(error)) return
        call check(error, b1%u_res, b2%u_res, rtol=0.0_dp, message='u_res omitted vs explicit')
        if (allocated(error)) return
        call check(error, b1%u_m1 > 0.0_dp, 'the block slides (eta = 0.6 < 1)')
        if (allocated(error)) return
        call check(error, b1%eta1, 0.3_dp/0.5_dp, rtol=1.0e-15_dp, message='eta1 = mu g/A_g')
        if (allocated(error)) return
        call block_response(0.3_dp, 0.5_dp, 0.6_dp, -3.0_dp, g=9.81_dp, res=b2, stat=stat)
        call check(error, abs(b2%u_m1 - b1%u_m1) > 1.0e-6_dp*b1%u_m1, 'g = 9.81 changes u_m1')
        if (allocated(error)) return
        call inclined_resistances(0.4_dp, 0.5_dp, 10.0_dp, eta1=e1, eta2=e2, k1=k1, k2=k2, &
                                  stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call inclined_resistances(0.4_dp, 0.5_dp, 10.0_dp, 0.0_dp, f1, f2, j1, j2, stat)
        call check(error, e1, f1, rtol=0.0_dp, message='eta1 omitted vs explicit')
        if (allocated(error)) return
        call check(error, e2, f2, rtol=0.0_dp, message='eta2 omitted vs explicit')
        if (allocated(error)) return
        call check(error, k1, j1, rtol=0.0_dp, message='k1 omitted vs explicit')
        if (allocated(error)) return
        call check(error, k2, j2, rtol=0.0_dp, message='k2 omitted vs explicit')
        if (allocated(error)) return
        call newmark_incline(0.45_dp, 12.0_dp, blk=n1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call newmark_incline(0.45_dp, 12.0_dp, 0.0_dp, .true., n2, stat)
        call check(error, n1%ky, n2%ky, rtol=0.0_dp, message='ky omitted vs explicit')
        if (allocated(error)) return
        call check(error, n1%ky_up, n2%ky_up, rtol=0.0_dp, message='ky_up omitted vs explicit')
        if (allocated(error)) return
        call check(error, n1%k_down, n2%k_down, rtol=0.0_dp, message='k_down')
        if (allocated(error)) return
        call newmark_incline(0.45_dp, 12.0_dp, along_plane=.false., blk=n2, stat=stat)
        call check(error, n2%k_down, 1.0_dp, rtol=0.0_dp, message='along_plane = .false.')
    end subroutine test_sliding

    subroutine test_pulses(error)
        type(test_error), allocatable, intent(out) :: error
        type(pulse_t) :: p1, p2
        real(dp), parameter :: tau(4) = [0.1_dp, 0.7_dp, 1.3_dp, 2.5_dp]
        real(dp) :: a1(4), v1(4), d1(4), a2(4), v2(4), d2(4), vg1, dg1, vg2, dg2
        integer :: stat, i
        p1 = exponential_pulse(2.0_dp, 0.5_dp, -3.0_dp)
        p2 = exponential_pulse(2.0_dp, 0.5_dp, -3.0_dp, .false.)
        call check(error, (p1%full .eqv. p2%full) .and. .not. p1%full, 'full = .false.')
        if (allocated(error)) return
        p1 = triangular_pulse(2.0_dp, 0.5_dp)
        call check(error, p1%peak_frac, 0.5_dp, rtol=0.0_dp, message='peak_frac = 0.5')
        if (allocated(error)) return
        call exp_pulse(tau, [-3.0_dp], a=a1, v=v1, d=d1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call exp_pulse(tau, [-3.0_dp], .false., a2, v2, d2, stat)
        do i = 1, 4
            call check(error, d1(i), d2(i), rtol=0.0_dp, message='exp_pulse d omitted')
            if (allocated(error)) return
        end do
        ! one lobe: nothing after tau = 1
        call check(error, a1(4), 0.0_dp, atol=0.0_dp, message='one lobe: a = 0 at tau = 2.5')
        if (allocated(error)) return
        call exp_pulse_peaks(-3.0_dp, vg=vg1, dg=dg1, stat=stat)
        call exp_pulse_peaks(-3.0_dp, .false., vg2, dg2, stat)
        call check(error, vg1, vg2, rtol=0.0_dp, message='exp_pulse_peaks vg')
        if (allocated(error)) return
        call check(error, dg1, dg2, rtol=0.0_dp, message='exp_pulse_peaks dg')
    end subroutine test_pulses

    subroutine test_sliding_closed(error)
        type(test_error), allocatable, intent(out) :: error
        type(half_cycle_t) :: h1, h2
        type(full_cycle_t) :: f1, f2
        real(dp) :: t1, t2, r1(6), r2(6)
        integer :: stat, i
        call yield_time(0.4_dp, -2.0_dp, tau_y=t1, stat=stat)
        call yield_time(0.4_dp, -2.0_dp, 1.0_dp, t2, stat)
        call check(error, t1, t2, rtol=0.0_dp, message='yield_time')
        if (allocated(error)) return
        call half_cycle(0.4_dp, -2.0_dp, res=h1, stat=stat)
        call half_cycle(0.4_dp, -2.0_dp, 1.0_dp, h2, stat)
        call check(error, h1%um, h2%um, rtol=0.0_dp, message='half_cycle um')
        if (allocated(error)) return
        call check(error, h1%tau_y, t1, rtol=0.0_dp, message='half_cycle onset = yield_time')
        if (allocated(error)) return
        call full_cycle(0.4_dp, 0.5_dp, -2.0_dp, res=f1, stat=stat)
        call full_cycle(0.4_dp, 0.5_dp, -2.0_dp, 1.0_dp, .false., f2, stat)
        call check(error, f1%um1, f2%um1, rtol=0.0_dp, message='full_cycle um1')
        if (allocated(error)) return
        call check(error, f1%tau_y2, f2%tau_y2, rtol=0.0_dp, message='full_cycle tau_y2')
        if (allocated(error)) return
        call full_cycle(0.4_dp, 0.5_dp, -2.0_dp, static_factor=1.2_dp, res=f2, stat=stat)
        call check(error, f2%tau_y1 > f1%tau_y1, 'static friction delays the onset')
        if (allocated(error)) return
        call table_1_3(-2.0_dp, ratios=r1, stat=stat)
        call table_1_3(-2.0_dp, .false., r2, stat)
        do i = 1, 6
            call check(error, r1(i), r2(i), rtol=0.0_dp, message='table_1_3')
            if (allocated(error)) return
        end do
    end subroutine test_sliding_closed

    subroutine test_bodies(error)
        type(test_error), allocatable, intent(out) :: error
        type(rocking_block_t) :: k1, k2
        type(rocking_body_t) :: c1, c2
        integer :: stat
        call rectangular_block(0.2_dp, 0.8_dp, blk=k1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call rectangular_block(0.2_dp, 0.8_dp, STANDARD_GRAVITY, k2, stat)
        call check(error, k1%p, k2%p, rtol=0.0_dp, message='rectangular_block p')
        if (allocated(error)) return
        call check(error, k1%p, sqrt(3.0_dp*9.80665_dp/(4.0_dp*hypot(0.2_dp, 0.8_dp))), &
                   rtol=1.0e-15_dp, message='p = sqrt(3 g/(4 R)), g = 9.80665')
        if (allocated(error)) return
        call symmetric_block(0.5_dp, 0.25_dp, 4.0_dp/3.0_dp, blk=k2, stat=stat)
        call check(error, k2%p, sqrt(3.0_dp*9.80665_dp/(4.0_dp*0.5_dp)), rtol=1.0e-15_dp, &
                   message='symmetric_block p')
        if (allocated(error)) return
        call cylinder_props(0.5_dp, 1.5_dp, body=c1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call cylinder_props(0.5_dp, 1.5_dp, 1.0_dp, STANDARD_GRAVITY, c2, stat)
        call check(error, c1%j_o, c2%j_o, rtol=0.0_dp, message='cylinder J_o')
        if (allocated(error)) return
        call check(error, c1%mass, 1.0_dp, rtol=0.0_dp, message='cylinder mass = 1 kg')
        if (allocated(error)) return
        call check(error, c1%g, 9.80665_dp, rtol=0.0_dp, message='cylinder g')
        if (allocated(error)) return
        call block_props(0.2_dp, 0.8_dp, body=c1, stat=stat)
        call block_props(0.2_dp, 0.8_dp, 1.0_dp, STANDARD_GRAVITY, c2, stat)
        call check(error, c1%j_o, c2%j_o, rtol=0.0_dp, message='block J_o')
        if (allocated(error)) return
        ! J_o = 4/3 m R^2 of a uniform block, m = 1 kg
        call check(error, c1%j_o, 4.0_dp/3.0_dp*(0.2_dp**2 + 0.8_dp**2), rtol=1.0e-15_dp, &
                   message='block J_o = 4/3 m R^2')
    end subroutine test_bodies

    subroutine test_oscillator(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 200
        real(dp) :: accel(n), z1(n), v1(n), a1(n), z2(n), v2(n), a2(n), sa1, sa2
        integer :: stat, i
        do i = 1, n
            accel(i) = 0.3_dp*sin(2.0_dp*pi*(i - 1)*0.01_dp/0.4_dp)
        end do
        call sdof_response(accel, 0.01_dp, 0.5_dp, disp=z1, vel=v1, acc=a1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call sdof_response(accel, 0.01_dp, 0.5_dp, 0.05_dp, STANDARD_GRAVITY, z2, v2, a2, stat)
        do i = 1, n, 37
            call check(error, z1(i), z2(i), rtol=0.0_dp, message='sdof_response z')
            if (allocated(error)) return
            call check(error, a1(i), a2(i), rtol=0.0_dp, message='sdof_response a')
            if (allocated(error)) return
        end do
        call spectral_acceleration(accel, 0.01_dp, 0.5_dp, sa=sa1, stat=stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call spectral_acceleration(accel, 0.01_dp, 0.5_dp, 0.05_dp, STANDARD_GRAVITY, sa2, stat)
        call check(error, sa1, sa2, rtol=0.0_dp, message='spectral_acceleration')
        if (allocated(error)) return
        call spectral_acceleration(accel, 0.01_dp, 0.5_dp, damping=0.2_dp, sa=sa2, stat=stat)
        call check(error, sa2 < sa1, 'more damping, lower Sa')
    end subroutine test_oscillator

end module test_optional_args
