!> EN 1998-1 3.2.3.1.2(4) record-suite check (seispulse_record_suite) on hand arrays: the
!> check grid (ends exact, 10^(k/4) between them, extras kept or dropped, duplicates
!> removed), the mean, the ratios, the least ratio and its period, (M.1)-(M.3) written out
!> as numbers here, the boundary 0.9 x target, scaling laws, the record counts of rules (a)
!> and 4.3.3.4.3(3), and bad input (messages name the parameter and the record). The check
!> from the records (ec8_suite_check_records): the target spectra against the code
!> routines, and a narrow trough between the periods of a coarse grid that the refinement
!> finds as a brute-force scan of 20000 periods does.
module test_record_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_record_suite, only: SUITE_FIT_LINEAR, SUITE_FIT_LOG, suite_check_t, &
                                      suite_records_grid, SUITE_SPECTRUM_FRACTION, &
                                      suite_check_periods, ec8_suite_check, suite_target_t, &
                                      SUITE_TARGET_EC8, SUITE_TARGET_EAK, suite_target_values, &
                                      suite_target_pga, suite_target_corners, &
                                      ec8_suite_check_records, suite_records_room, &
                                      SUITE_RULE_PGA, SUITE_RULE_SPECTRUM
    use seispulse_codes, only: ec8_elastic_spectrum, EC8_SPECTRUM_TYPE_2, EC8_GROUND_B, &
                               EC8_GROUND_C
    use seispulse_eak2000, only: eak2000_elastic_spectrum, EAK_GROUND_B
    use seispulse_sdof_sim, only: sdof_spectrum, pseudo_spectra
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_special, only: pi
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_record_suite

    !> The hand suite: T1 = 1 s, grid 0.2, 0.4, 1, 2 s, three records.
    real(dp), parameter :: grid(4) = [0.2_dp, 0.4_dp, 1.0_dp, 2.0_dp]
    real(dp), parameter :: tgt(4) = [1.0_dp, 1.0_dp, 0.5_dp, 0.25_dp]
    real(dp), parameter :: rec(4, 3) = reshape([1.2_dp, 1.0_dp, 0.5_dp, 0.2_dp, &
                                                0.9_dp, 1.1_dp, 0.4_dp, 0.25_dp, &
                                                1.2_dp, 0.9_dp, 0.6_dp, 0.15_dp], [4, 3])
    real(dp), parameter :: peak(3) = [0.5_dp, 0.4_dp, 0.3_dp]

contains

    subroutine collect_record_suite(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('grid: ends exact, 10^(k/4), extras in/out, duplicates, order', &
                              test_grid), &
                 new_unittest('grid: bad t1, n_points, room, NaN extra', test_grid_bad), &
                 new_unittest('hand suite: mean, ratios, least ratio, (M.1)-(M.3), own suite', &
                              test_hand), &
                 new_unittest('boundary: exactly 0.9 x target and PGA = target pass; less fails', &
                              test_boundary), &
                 new_unittest('scaling: c x records -> common_scale/c; c x target -> 1/c', &
                              test_scaling), &
                 new_unittest('counts: n = 2 refused, min_records, 6 and 7 records', test_counts), &
                 new_unittest('bad input: t1, fit, sizes, grid, target, PGA, zero PSA', test_bad), &
                 new_unittest('target: EC8 and EAK spectra, T = 0, corners, refusals', &
                              test_target), &
                 new_unittest('records: a trough between grid periods = 20000-period scan', &
                              test_trough), &
                 new_unittest('records: refusals name the record', test_records_bad)]
    end subroutine collect_record_suite

    !> errmsg must contain `part` and stat must be SEISPULSE_INVALID_INPUT.
    subroutine check_refused(error, stat, errmsg, part)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: stat
        character(len=*), intent(in) :: errmsg, part
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'stat for "'//part//'"')
        if (allocated(error)) return
        call check(error, index(errmsg, part) > 0, 'message "'//trim(errmsg)// &
                   '" lacks "'//part//'"')
    end subroutine check_refused

    subroutine test_grid(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p(12), q(5)
        real(dp) :: r4
        integer :: n, stat
        character(len=256) :: msg
        r4 = sqrt(sqrt(10.0_dp))   ! 10^(1/4)
        call suite_check_periods(0.5_dp, 5, [0.5_dp, 0.05_dp, 3.0_dp, 0.5_dp, 0.1_dp, 0.4_dp, &
                                 1.0_dp], p, n, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, n, 7, 'n: 5 log points + 0.4 + 0.5 (0.05, 3 dropped; 0.5, 0.1, 1 twice)')
        if (allocated(error)) return
        call check(error, [p(1), p(7)], [0.2_dp*0.5_dp, 2.0_dp*0.5_dp], rtol=0.0_dp, &
                   message='ends exact')
        if (allocated(error)) return
        call check(error, p(1:7), [0.1_dp, 0.1_dp*r4, 0.1_dp*r4**2, 0.4_dp, 0.5_dp, &
                                   0.1_dp*r4**3, 1.0_dp], rtol=4.0e-16_dp, message='grid')
        if (allocated(error)) return
        call check(error, [p(4), p(5)], [0.4_dp, 0.5_dp], rtol=0.0_dp, &
                   message='extras kept as given')
        if (allocated(error)) return
        call check(error, p(8:), [(0.0_dp, n = 8, 12)], atol=0.0_dp, rtol=0.0_dp, &
                   message='unused tail zero')
        if (allocated(error)) return
        ! n_points = 2: the two ends only; no extras
        call suite_check_periods(3.0_dp, 2, [real(dp) ::], q, n, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. n == 2, 'two points')
        if (allocated(error)) return
        call check(error, q(1:2), [0.2_dp*3.0_dp, 2.0_dp*3.0_dp], rtol=0.0_dp, &
                   message='two ends')
    end subroutine test_grid

    subroutine test_grid_bad(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p(10), nan
        integer :: n, stat
        character(len=256) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        msg = ''
        call suite_check_periods(0.0_dp, 5, [real(dp) ::], p, n, stat, msg)
        call check_refused(error, stat, msg, &
                           't1 = 0.0: the fundamental period T1 (s) must be finite and > 0')
        if (allocated(error)) return
        call suite_check_periods(nan, 5, [real(dp) ::], p, n, stat, msg)
        call check_refused(error, stat, msg, 't1 = NaN')
        if (allocated(error)) return
        call suite_check_periods(-1.0_dp, 5, [real(dp) ::], p, n, stat, msg)
        call check_refused(error, stat, msg, 't1 = -1')
        if (allocated(error)) return
        call suite_check_periods(1.0_dp, 1, [real(dp) ::], p, n, stat, msg)
        call check_refused(error, stat, msg, 'n_points = 1')
        if (allocated(error)) return
        call suite_check_periods(1.0_dp, 8, [0.5_dp, 0.6_dp, 0.7_dp], p, n, stat, msg)
        call check_refused(error, stat, msg, 'periods: has room for 10')
        if (allocated(error)) return
        call suite_check_periods(1.0_dp, 5, [0.5_dp, nan], p, n, stat, msg)
        call check_refused(error, stat, msg, 'extra(2) = NaN')
    end subroutine test_grid_bad

    subroutine test_hand(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_check_t) :: c
        real(dp) :: s(3), m(4), ratio(4), own(4), s_lin(3), s_log(3), om(4), opga
        integer :: stat, k
        character(len=256) :: msg
        ! (M.2) by hand: sum p t / sum p^2 per record
        s_lin = [2.5_dp/2.73_dp, 2.2625_dp/2.2425_dp, 2.4375_dp/2.6325_dp]
        ! (M.3) by hand: (prod t/p)^(1/4)
        s_log = [(1.25_dp/1.2_dp)**0.25_dp, (1.25_dp/0.99_dp)**0.25_dp, &
                 (1.0_dp/1.2_dp/0.9_dp*(0.5_dp/0.6_dp)*(0.25_dp/0.15_dp))**0.25_dp]
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg, ratio=ratio, own_mean=own)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, m, [1.1_dp, 1.0_dp, 0.5_dp, 0.2_dp], rtol=1.0e-15_dp, message='mean')
        if (allocated(error)) return
        call check(error, ratio, [1.1_dp, 1.0_dp, 1.0_dp, 0.8_dp], rtol=1.0e-15_dp, &
                   message='ratio')
        if (allocated(error)) return
        call check(error, c%n_records, 3)
        if (allocated(error)) return
        call check(error, [c%t1, c%t_low, c%t_high], [1.0_dp, 0.2_dp, 2.0_dp], rtol=0.0_dp, &
                   message='t1 and range')
        if (allocated(error)) return
        call check(error, [c%pga_mean, c%pga_target, c%pga_ratio], [0.4_dp, 0.5_dp, 0.8_dp], &
                   rtol=1.0e-15_dp, message='pga')
        if (allocated(error)) return
        call check(error, [c%min_ratio, c%t_min_ratio], [0.8_dp, 2.0_dp], rtol=1.0e-15_dp, &
                   message='least ratio')
        if (allocated(error)) return
        call check(error, .not. c%pga_ok .and. .not. c%spectrum_ok .and. c%count_ok .and. &
                   .not. c%mean_allowed .and. .not. c%passed, 'verdicts')
        if (allocated(error)) return
        ! (M.1): max(0.5/0.4, 0.9 x 0.25/0.2) = max(1.25, 1.125)
        call check(error, c%common_scale, 1.25_dp, rtol=1.0e-15_dp, message='common_scale')
        if (allocated(error)) return
        call check(error, s, s_lin, rtol=1.0e-15_dp, message='own_scale linear (M.2)')
        if (allocated(error)) return
        om = 0.0_dp
        opga = 0.0_dp
        do k = 1, 3
            om = om + s_lin(k)*rec(:, k)/3.0_dp
            opga = opga + s_lin(k)*peak(k)/3.0_dp
        end do
        call check(error, own, om, rtol=1.0e-14_dp, message='own_mean')
        if (allocated(error)) return
        call check(error, c%own_pga_ratio, opga/0.5_dp, rtol=1.0e-14_dp, message='own pga')
        if (allocated(error)) return
        call check(error, c%own_min_ratio, minval(om/tgt), rtol=1.0e-14_dp, &
                   message='own min ratio')
        if (allocated(error)) return
        call check(error, c%own_t_min_ratio, grid(minloc(om/tgt, 1)), rtol=0.0_dp, &
                   message='own T of min')
        if (allocated(error)) return
        call check(error, c%own_passed .eqv. (opga >= 0.5_dp .and. all(om >= 0.9_dp*tgt)), &
                   'own_passed')
        if (allocated(error)) return
        ! a common scale of 1.25 makes the suite pass: (b) exactly at its limit
        call ec8_suite_check(grid, 1.25_dp*rec, 1.25_dp*peak, tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. c%passed, 'passes at common_scale')
        if (allocated(error)) return
        call check(error, c%common_scale, 1.0_dp, rtol=1.0e-15_dp, message='then common 1')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LOG, c, s, m, &
                             stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, s, s_log, rtol=1.0e-15_dp, message='own_scale log (M.3)')
    end subroutine test_hand

    subroutine test_boundary(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_check_t) :: c
        real(dp) :: p(4, 4), s(4), m(4)
        integer :: stat, k
        character(len=256) :: msg
        ! four equal records: the mean is exact (sum of 4 equal terms, / 4)
        do k = 1, 4
            p(:, k) = 0.9_dp*tgt
        end do
        call ec8_suite_check(grid, p, [0.5_dp, 0.5_dp, 0.5_dp, 0.5_dp], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, c%pga_ok .and. c%spectrum_ok .and. c%passed, 'at the boundary')
        if (allocated(error)) return
        call check(error, [c%min_ratio, c%pga_ratio, c%common_scale], [0.9_dp, 1.0_dp, 1.0_dp], &
                   rtol=2.0e-16_dp, message='ratios at the boundary')
        if (allocated(error)) return
        ! one value 1e-9 lower (relative): (c) fails there; PGA 1e-9 lower: (b) fails
        p(3, 2) = p(3, 2)*(1.0_dp - 4.0e-9_dp)
        call ec8_suite_check(grid, p, [0.5_dp, 0.5_dp, 0.5_dp, 0.5_dp*(1.0_dp - 4.0e-9_dp)], &
                             tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        call check(error, .not. c%spectrum_ok .and. .not. c%pga_ok .and. .not. c%passed, &
                   'just below')
        if (allocated(error)) return
        call check(error, c%t_min_ratio, 1.0_dp, rtol=0.0_dp, message='where')
        if (allocated(error)) return
        call check(error, c%min_ratio, 0.9_dp*(1.0_dp - 1.0e-9_dp), rtol=1.0e-15_dp, &
                   message='least ratio just below')
        if (allocated(error)) return
        call check(error, c%common_scale, 1.0_dp/(1.0_dp - 1.0e-9_dp), rtol=1.0e-15_dp, &
                   message='common scale just above 1')
    end subroutine test_boundary

    subroutine test_scaling(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_check_t) :: c, cc
        real(dp) :: s(3), sc(3), m(4), p(4, 3)
        real(dp), parameter :: cf = 2.75_dp
        integer :: stat, fit
        character(len=256) :: msg
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call ec8_suite_check(grid, cf*rec, cf*peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, cc, &
                             sc, m, stat, msg)
        call check(error, cc%common_scale, c%common_scale/cf, rtol=1.0e-15_dp, &
                   message='common_scale of c x records')
        if (allocated(error)) return
        call check(error, sc, s/cf, rtol=1.0e-15_dp, message='own_scale of c x records')
        if (allocated(error)) return
        ! record 2 = c x target: own scale 1/c for both fits
        p = rec
        p(:, 2) = cf*tgt
        do fit = SUITE_FIT_LINEAR, SUITE_FIT_LOG
            call ec8_suite_check(grid, p, peak, tgt, 0.5_dp, 1.0_dp, fit, c, s, m, stat, msg)
            call check(error, s(2), 1.0_dp/cf, rtol=1.0e-15_dp, message='own scale 1/c')
            if (allocated(error)) return
        end do
    end subroutine test_scaling

    subroutine test_counts(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_check_t) :: c
        real(dp) :: p(4, 7), s(7), m(4)
        integer :: stat, k
        character(len=256) :: msg
        do k = 1, 7
            p(:, k) = tgt
        end do
        msg = ''
        call ec8_suite_check(grid, p(:, 1:2), peak(1:2), tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, &
                             c, s(1:2), m, stat, msg)
        call check_refused(error, stat, msg, 'n = 2 records: the suite needs at least 3')
        if (allocated(error)) return
        call ec8_suite_check(grid, p(:, 1:2), [0.5_dp, 0.5_dp], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s(1:2), m, stat, msg, min_records=2)
        call check(error, stat == SEISPULSE_SUCCESS .and. .not. c%count_ok .and. &
                   c%pga_ok .and. c%spectrum_ok .and. .not. c%passed, 'two records allowed')
        if (allocated(error)) return
        call ec8_suite_check(grid, p(:, 1:6), [(0.5_dp, k = 1, 6)], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s(1:6), m, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. c%passed .and. .not. c%mean_allowed, &
                   'six records')
        if (allocated(error)) return
        call ec8_suite_check(grid, p, [(0.5_dp, k = 1, 7)], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check(error, stat == SEISPULSE_SUCCESS .and. c%passed .and. c%mean_allowed, &
                   'seven records')
        if (allocated(error)) return
        call ec8_suite_check(grid, p, [(0.5_dp, k = 1, 7)], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg, min_records=8)
        call check_refused(error, stat, msg, 'n = 7 records: the suite needs at least 8')
        if (allocated(error)) return
        call ec8_suite_check(grid, p, [(0.5_dp, k = 1, 7)], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg, min_records=0)
        call check_refused(error, stat, msg, 'min_records = 0')
    end subroutine test_counts

    subroutine test_bad(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_check_t) :: c
        real(dp) :: p(4, 3), s(3), m(4), nan, t(4)
        integer :: stat
        character(len=256) :: msg
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        msg = ''
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 0.0_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, &
                           't1 = 0.0: the fundamental period T1 (s) must be finite and > 0')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, nan, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 't1 = NaN')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 1.0_dp, 3, c, s, m, stat, msg)
        call check_refused(error, stat, msg, 'fit = 3')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec(1:3, :), peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, &
                             s, m, stat, msg)
        call check_refused(error, stat, msg, 'psa: must have shape (4, 3)')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, &
                             s(1:2), m, stat, msg)
        call check_refused(error, stat, msg, 'own_scale')
        if (allocated(error)) return
        ! the grid must lie in [0.2 T1, 2 T1] and ascend
        call ec8_suite_check(grid, rec, peak, tgt, 0.5_dp, 0.9_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 'periods(4) = 2')
        if (allocated(error)) return
        call ec8_suite_check([0.2_dp, 1.0_dp, 0.4_dp, 2.0_dp], rec, peak, tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check_refused(error, stat, msg, 'periods(3) = 0.4')
        if (allocated(error)) return
        t = tgt
        t(2) = 0.0_dp
        call ec8_suite_check(grid, rec, peak, t, 0.5_dp, 1.0_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 'target(2) = 0.0: the target spectrum (g) at T = 0.4')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, peak, tgt, nan, 1.0_dp, SUITE_FIT_LINEAR, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 'target_pga = NaN')
        if (allocated(error)) return
        call ec8_suite_check(grid, rec, [0.5_dp, nan, 0.3_dp], tgt, 0.5_dp, 1.0_dp, &
                             SUITE_FIT_LINEAR, c, s, m, stat, msg)
        call check_refused(error, stat, msg, 'pga(2) = NaN: the PGA (g) of record 2')
        if (allocated(error)) return
        p = rec
        p(3, 3) = 0.0_dp
        call ec8_suite_check(grid, p, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LOG, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 'psa(3, 3) = 0.0: the 5 % PSA (g) of record 3')
        if (allocated(error)) return
        p(3, 3) = nan
        call ec8_suite_check(grid, p, peak, tgt, 0.5_dp, 1.0_dp, SUITE_FIT_LOG, c, s, m, &
                             stat, msg)
        call check_refused(error, stat, msg, 'psa(3, 3) = NaN')
    end subroutine test_bad

    subroutine test_target(error)
        type(test_error), allocatable, intent(out) :: error
        type(suite_target_t) :: t
        real(dp) :: per(5), v(5), ref(5), pga, c(3)
        integer :: stat, n
        character(len=256) :: msg
        per = [0.0_dp, 0.1_dp, 0.4_dp, 1.3_dp, 3.0_dp]
        t = suite_target_t(code=SUITE_TARGET_EC8, spectrum_type=EC8_SPECTRUM_TYPE_2, ag=0.24_dp, &
                           ground=EC8_GROUND_C)
        call suite_target_values(t, per, v, stat, msg)
        call ec8_elastic_spectrum(per, 0.24_dp, EC8_SPECTRUM_TYPE_2, EC8_GROUND_C, 5.0_dp, ref, &
                                  stat, msg)
        call check(error, v, ref, rtol=0.0_dp, message='EC8 type 2 C')
        if (allocated(error)) return
        ! a_g S: type 2, ground C: S = 1.5 (EN 1998-1 Table 3.3)
        call suite_target_pga(t, pga, stat, msg)
        call check(error, pga, 0.24_dp*1.5_dp, rtol=1.0e-15_dp, message='a_g S')
        if (allocated(error)) return
        call suite_target_corners(t, c, n, stat, msg)
        call check(error, n == 3 .and. stat == SEISPULSE_SUCCESS, 'three corners')
        if (allocated(error)) return
        call check(error, c, [0.1_dp, 0.25_dp, 1.2_dp], rtol=0.0_dp, message='TB TC TD type 2 C')
        if (allocated(error)) return
        t = suite_target_t(code=SUITE_TARGET_EAK, alpha=0.24_dp, ground=EAK_GROUND_B, &
                           importance=1.15_dp, exponent=1.0_dp)
        call suite_target_values(t, per, v, stat, msg)
        call eak2000_elastic_spectrum(per, 0.24_dp, EAK_GROUND_B, 1.15_dp, 5.0_dp, 0.0_dp, &
                                      1.0_dp, ref, stat, msg)
        call check(error, v, ref, rtol=0.0_dp, message='EAK B')
        if (allocated(error)) return
        call suite_target_pga(t, pga, stat, msg)
        call check(error, pga, 1.15_dp*0.24_dp, rtol=1.0e-15_dp, message='gamma_I A')
        if (allocated(error)) return
        call suite_target_corners(t, c, n, stat, msg)
        call check(error, n == 2 .and. c(3) <= 0.0_dp, 'two corners')
        if (allocated(error)) return
        call check(error, c(1:2), [0.15_dp, 0.6_dp], rtol=0.0_dp, message='EAK T1 T2 ground B')
        if (allocated(error)) return
        ! Phi_e written out: (K.1)-(K.3) with q = theta = 1 and eta(5 %) = 1, gamma_I A =
        ! 1.15 x 0.24 g, beta0 = 2.5, ground B T1 = 0.15 s, T2 = 0.6 s (doc/eak2000.md)
        call check(error, v, 1.15_dp*0.24_dp*[1.0_dp, 1.0_dp + (0.1_dp/0.15_dp)*1.5_dp, 2.5_dp, &
                   2.5_dp*(0.6_dp/1.3_dp), 2.5_dp*(0.6_dp/3.0_dp)], rtol=1.0e-14_dp, &
                   message='EAK B exponent 1, written out')
        if (allocated(error)) return
        t%exponent = 2.0_dp/3.0_dp
        call suite_target_values(t, per, v, stat, msg)
        call check(error, v, 1.15_dp*0.24_dp*[1.0_dp, 2.0_dp, 2.5_dp, &
                   2.5_dp*(0.6_dp/1.3_dp)**(2.0_dp/3.0_dp), &
                   2.5_dp*(0.6_dp/3.0_dp)**(2.0_dp/3.0_dp)], rtol=1.0e-14_dp, &
                   message='EAK B exponent 2/3, written out')
        if (allocated(error)) return
        msg = ''
        t = suite_target_t(code=SUITE_TARGET_EC8, ag=0.0_dp)
        call suite_target_pga(t, pga, stat, msg)
        call check_refused(error, stat, msg, 'ag = 0.0: the design ground acceleration')
        if (allocated(error)) return
        t = suite_target_t(code=SUITE_TARGET_EAK, alpha=0.2_dp, ground=5)
        call suite_target_pga(t, pga, stat, msg)
        call check_refused(error, stat, msg, 'ground category X')
        if (allocated(error)) return
        t = suite_target_t(code=3)
        call suite_target_pga(t, pga, stat, msg)
        call check_refused(error, stat, msg, 'code = 3')
    end subroutine test_target

    !> Three windowed sines (periods 0.25, 0.6, 1.5 s): the mean/target ratio has a trough
    !> near 0.395 s; a 6-point grid over [0.2, 2] s misses it by 23 %. The refined least
    !> ratio equals the least of 20000 log-spaced periods to 1e-6, and its period is on the
    !> returned grid with that ratio.
    subroutine test_trough(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: ns = 4801, nscan = 20000
        real(dp), parameter :: step = 0.005_dp
        real(dp), parameter :: tp(3) = [0.25_dp, 0.6_dp, 1.5_dp], amp(3) = [0.3_dp, 0.25_dp, &
                                                                               0.2_dp]
        real(dp) :: accel(3*ns), t, env, scan_t(nscan), tgt(nscan), mean(nscan)
        real(dp), allocatable :: sd(:, :), sv(:, :), sa(:, :), psv(:, :), ps(:, :)
        real(dp) :: per(suite_records_room(6, 0)), psa(suite_records_room(6, 0), 3), pga(3)
        real(dp) :: tv(suite_records_room(6, 0)), m(suite_records_room(6, 0)), &
                    r(suite_records_room(6, 0)), om(suite_records_room(6, 0)), own(3), best
        real(dp) :: g(suite_records_room(6, 0))
        type(suite_target_t) :: target
        type(suite_check_t) :: c
        integer :: k, i, stat, n, at, ng
        character(len=256) :: msg
        do k = 1, 3
            do i = 1, ns
                t = (i - 1)*step
                env = sin(pi*min(t/(8.0_dp*tp(k)), 1.0_dp))**2
                accel((k - 1)*ns + i) = amp(k)*sin(2.0_dp*pi*t/tp(k))*env
                if (t > 8.0_dp*tp(k)) accel((k - 1)*ns + i) = 0.0_dp
            end do
        end do
        target = suite_target_t(code=SUITE_TARGET_EC8, ag=0.3_dp, ground=EC8_GROUND_B)
        call ec8_suite_check_records(accel, [1, ns + 1, 2*ns + 1], [ns, ns, ns], &
                                     [step, step, step], target, 1.0_dp, SUITE_FIT_LINEAR, c, &
                                     per, n, psa, pga, tv, m, r, om, own, stat, msg, n_points=6)
        call check(error, stat, SEISPULSE_SUCCESS, trim(msg))
        if (allocated(error)) return
        ! the brute-force scan
        do i = 1, nscan
            scan_t(i) = 0.2_dp*10.0_dp**(real(i - 1, dp)/real(nscan - 1, dp))
        end do
        allocate(sd(nscan, 1), sv(nscan, 1), sa(nscan, 1), psv(nscan, 1), ps(nscan, 1))
        mean = 0.0_dp
        do k = 1, 3
            call sdof_spectrum(accel((k - 1)*ns + 1:k*ns), step, scan_t, [0.05_dp], &
                               STANDARD_GRAVITY, sd, sv, sa, stat, msg)
            call pseudo_spectra(scan_t, sd, STANDARD_GRAVITY, 0.0_dp, psv, ps)
            mean = mean + ps(:, 1)/3.0_dp
        end do
        call ec8_elastic_spectrum(scan_t, 0.3_dp, ground=EC8_GROUND_B, se=tgt, stat=stat)
        at = minloc(mean/tgt, 1)
        best = mean(at)/tgt(at)
        call check(error, c%min_ratio, best, rtol=1.0e-6_dp, message='refined = scan')
        if (allocated(error)) return
        call check(error, c%t_min_ratio, scan_t(at), rtol=1.0e-3_dp, message='its period')
        if (allocated(error)) return
        call check(error, c%grid_min_ratio > 1.1_dp*best, 'the grid alone misses it')
        if (allocated(error)) return
        call check(error, c%n_searched > 0 .and. .not. c%spectrum_ok .and. .not. c%passed, &
                   'searched; fails (c)')
        if (allocated(error)) return
        ! (M.1) from the refined least ratio: rule (c) sets it
        call check(error, c%common_scale, max(c%pga_target/c%pga_mean, 0.9_dp/best), &
                   rtol=1.0e-6_dp, message='common_scale')
        if (allocated(error)) return
        call check(error, c%scale_rule, SUITE_RULE_SPECTRUM)
        if (allocated(error)) return
        ! the refined period is on the returned grid with the least ratio
        at = minloc(abs(per(1:n) - c%t_min_ratio), 1)
        call check(error, per(at), c%t_min_ratio, rtol=0.0_dp, message='on the grid')
        if (allocated(error)) return
        call check(error, r(at), c%min_ratio, rtol=0.0_dp, message='ratio there')
        if (allocated(error)) return
        call check(error, minval(r(1:n)), c%min_ratio, rtol=0.0_dp, message='least of table')
        if (allocated(error)) return
        call check(error, m(at), sum(psa(at, :))/3.0_dp, rtol=1.0e-15_dp, message='mean there')
        if (allocated(error)) return
        call check(error, all(per(2:n) > per(1:n - 1)) .and. n >= 9 .and. n <= 10, &
                   'grid ascending, 6 + T1 + TC + 1 or 2 refined')
        if (allocated(error)) return
        call check(error, c%own_min_ratio <= c%grid_own_min_ratio, 'own refined')
        if (allocated(error)) return
        do k = 1, 3
            call check(error, pga(k), maxval(abs(accel((k - 1)*ns + 1:k*ns))), rtol=0.0_dp, &
                       message='pga of record '//achar(48 + k))
            if (allocated(error)) return
        end do
        ! the check grid: 6 log-spaced periods, T1 = 1 s and TC = 0.5 s (TD = 2 T1 is an
        ! end, TB = 0.15 s lies below 0.2 T1); the refined periods come on top
        call check(error, c%n_grid, 8)
        if (allocated(error)) return
        call suite_records_grid(target, 1.0_dp, 6, [real(dp) ::], g, ng, stat, msg)
        call check(error, ng, c%n_grid)
        if (allocated(error)) return
        do i = 1, ng
            call check(error, minval(abs(per(1:n) - g(i))) <= 0.0_dp, 'grid period returned')
            if (allocated(error)) return
        end do
        call check(error, n - ng >= 1 .and. n - ng <= 2, 'one or two refined periods')
        if (allocated(error)) return
        call check(error, SUITE_SPECTRUM_FRACTION, 0.9_dp, rtol=0.0_dp, message='rule (c) 90 %')
    end subroutine test_trough

    subroutine test_records_bad(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: accel(300), per(16), psa(16, 3), pga(3), tv(16), m(16), r(16), om(16), own(3)
        type(suite_target_t) :: target
        type(suite_check_t) :: c
        integer :: stat, n, i, bad
        character(len=256) :: msg
        do i = 1, 300
            accel(i) = sin(real(i, dp)*0.3_dp)
        end do
        accel(201:300) = 0.0_dp
        target = suite_target_t(code=SUITE_TARGET_EC8, ag=0.3_dp, ground=EC8_GROUND_B)
        msg = ''
        call refused_record([1, 101, 201], [100, 100, 100], [0.01_dp, 0.01_dp, 0.01_dp], &
                            'record 3: its PGA is 0.0 g', 3)
        if (allocated(error)) return
        call refused_record([1, 101, 251], [100, 100, 100], [0.01_dp, 0.01_dp, 0.01_dp], &
                            'record 3: first = 251, npts = 100', 3)
        if (allocated(error)) return
        call refused_record([1, 101, 151], [100, 100, 50], [0.01_dp, 0.0_dp, 0.01_dp], &
                            'record 2: dt', 2)
        if (allocated(error)) return
        call ec8_suite_check_records(accel, [1, 101], [100, 100], [0.01_dp, 0.01_dp], target, &
                                     0.5_dp, SUITE_FIT_LINEAR, c, per, n, psa(:, 1:2), pga(1:2), &
                                     tv, m, r, om, own(1:2), stat, msg, n_points=10)
        call check_refused(error, stat, msg, 'records: 2 given; the suite needs at least 3')
        if (allocated(error)) return
        call ec8_suite_check_records(accel, [1, 101, 151], [100, 100, 50], [0.01_dp, 0.01_dp, &
                                     0.01_dp], target, 0.5_dp, SUITE_FIT_LINEAR, c, per(1:10), &
                                     n, psa, pga, tv, m, r, om, own, stat, msg, n_points=10)
        call check_refused(error, stat, msg, 'need room for 16 periods')
        if (allocated(error)) return
        target%ag = 0.0_dp
        call ec8_suite_check_records(accel, [1, 101, 151], [100, 100, 50], [0.01_dp, 0.01_dp, &
                                     0.01_dp], target, 0.5_dp, SUITE_FIT_LINEAR, c, per, n, &
                                     psa, pga, tv, m, r, om, own, stat, msg, n_points=10)
        call check_refused(error, stat, msg, 'ag = 0.0')
        if (allocated(error)) return
        call check(error, SUITE_RULE_PGA /= SUITE_RULE_SPECTRUM, 'rule codes differ')

    contains

        !> The check of three records (first, npts, dt) is refused with `part` in the
        !> message, and bad_record names record `which`.
        subroutine refused_record(first, npts, dt, part, which)
            integer, intent(in) :: first(3), npts(3), which
            real(dp), intent(in) :: dt(3)
            character(len=*), intent(in) :: part
            call ec8_suite_check_records(accel, first, npts, dt, target, 0.5_dp, &
                                         SUITE_FIT_LINEAR, c, per, n, psa, pga, tv, m, r, om, &
                                         own, stat, msg, n_points=10, bad_record=bad)
            call check_refused(error, stat, msg, part)
            if (allocated(error)) return
            call check(error, bad, which, 'bad_record')
        end subroutine refused_record
    end subroutine test_records_bad

end module test_record_suite
