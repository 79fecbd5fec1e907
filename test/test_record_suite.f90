!> EN 1998-1 3.2.3.1.2(4) record-suite check (seispulse_record_suite) on hand arrays: the
!> check grid (ends exact, 10^(k/4) between them, extras kept or dropped, duplicates
!> removed), the mean, the ratios, the least ratio and its period, (M.1)-(M.3) written out
!> as numbers here, the boundary 0.9 x target, scaling laws, the record counts of rules (a)
!> and 4.3.3.4.3(3), and bad input (messages name the parameter and the record).
module test_record_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_record_suite, only: SUITE_FIT_LINEAR, SUITE_FIT_LOG, suite_check_t, &
                                      suite_check_periods, ec8_suite_check
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
                 new_unittest('bad input: t1, fit, sizes, grid, target, PGA, zero PSA', test_bad)]
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

end module test_record_suite
