!> EN 1998-1 3.2.3.1.2(4) check of a suite of recorded accelerograms (admitted by
!> 3.2.3.1.3(2)) against the code's elastic spectrum (doc/record-suites.md).
!>
!> The rules: (a) at least 3 records; (b) the mean of the records' zero-period spectral
!> accelerations (their PGA) is not below a_g S, the elastic spectrum at T = 0; (c) over
!> [0.2 T1, 2 T1] (T1: the structure's fundamental period) no value of the mean 5 %-damped
!> elastic spectrum of the suite lies below 90 % of the code's elastic spectrum.
!> EN 1998-1 4.3.3.4.3(3): with at least 7 records the mean response may be used (else the
!> most unfavourable one), reported as `mean_allowed`.
!>
!> This module works on arrays only: the caller gives the check grid (`suite_check_periods`),
!> each record's 5 % pseudo-spectral acceleration (PSA) and PGA there (seispulse_sdof_sim's
!> sdof_spectrum with exact peaks) and the target spectrum. Besides the check it gives the
!> smallest common scale factor that makes the suite pass (M.1) and one scale factor per
!> record fitted to the target over the grid, linear (M.2) or in log space (M.3).
!>
!> Comparisons are made up to rounding: a value passes when it is not below its limit by
!> more than `suite_rtol` (relative), so that a suite scaled by `common_scale` passes.
module seispulse_record_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: finite_positive
    use seispulse_optval, only: optval
    use seispulse_format, only: real_str, int_str
    implicit none
    private

    public :: SUITE_FIT_LINEAR, SUITE_FIT_LOG, suite_rtol, suite_check_t
    public :: suite_check_periods, ec8_suite_check

    !> Per-record scale factor fitted to the target over the check grid: least squares on
    !> the ordinates (M.2) or on their logarithms (M.3).
    integer, parameter :: SUITE_FIT_LINEAR = 1
    integer, parameter :: SUITE_FIT_LOG = 2
    !> Relative rounding allowance of the comparisons (b) and (c) (dimensionless).
    real(dp), parameter :: suite_rtol = 1.0e-12_dp
    !> Relative allowance on the ends of [0.2 T1, 2 T1] for the periods given to
    !> ec8_suite_check (a grid computed elsewhere may differ there by rounding).
    real(dp), parameter :: range_rtol = 1.0e-9_dp
    !> The rules of EN 1998-1: at least 3 records (3.2.3.1.2(4)a), the mean response with 7
    !> (4.3.3.4.3(3)), PGA and 90 % of the spectrum over [0.2 T1, 2 T1].
    integer, parameter :: code_min_records = 3, mean_records = 7
    real(dp), parameter :: spectrum_fraction = 0.9_dp, low_factor = 0.2_dp, high_factor = 2.0_dp

    !> Outcome of ec8_suite_check (doc/record-suites.md section 2).
    type :: suite_check_t
        integer :: n_records = 0              !! records in the suite
        real(dp) :: t1 = 0.0_dp               !! fundamental period T1, s
        real(dp) :: t_low = 0.0_dp            !! 0.2 T1, s
        real(dp) :: t_high = 0.0_dp           !! 2 T1, s
        real(dp) :: pga_mean = 0.0_dp         !! mean PGA of the records, g
        real(dp) :: pga_target = 0.0_dp       !! the target at T = 0 (a_g S), g
        real(dp) :: pga_ratio = 0.0_dp        !! pga_mean/pga_target (-)
        logical :: pga_ok = .false.           !! (b): pga_mean >= pga_target
        real(dp) :: min_ratio = 0.0_dp        !! min over the grid of mean/target (-)
        real(dp) :: t_min_ratio = 0.0_dp      !! its period, s (the shortest if tied)
        logical :: spectrum_ok = .false.      !! (c): min_ratio >= 0.9
        logical :: count_ok = .false.         !! (a): n_records >= 3
        logical :: mean_allowed = .false.     !! n_records >= 7 (EN 1998-1 4.3.3.4.3(3))
        logical :: passed = .false.           !! (a) and (b) and (c)
        !> smallest s for which s x every record passes (b) and (c) (M.1) (-)
        real(dp) :: common_scale = 0.0_dp
        real(dp) :: own_pga_ratio = 0.0_dp    !! pga_ratio of the suite scaled by own_scale (-)
        real(dp) :: own_min_ratio = 0.0_dp    !! min_ratio of that suite (-)
        real(dp) :: own_t_min_ratio = 0.0_dp  !! its period, s
        logical :: own_passed = .false.       !! (a), (b) and (c) for that suite
    end type suite_check_t

contains

    !> The check grid: n_points periods spaced evenly in log T from 0.2 T1 to 2 T1 (both ends
    !> exact: 0.2_dp*t1 and 2_dp*t1), plus each value of extra(:) inside that range (the
    !> code spectrum's corners, the user's own periods); sorted ascending, exact duplicates
    !> removed. periods(:) must have room for n_points + size(extra); periods(n+1:) = 0.
    pure subroutine suite_check_periods(t1, n_points, extra, periods, n, stat, errmsg)
        real(dp), intent(in) :: t1            !! fundamental period T1, s, finite, > 0
        integer, intent(in) :: n_points       !! log-spaced periods, >= 2
        real(dp), intent(in) :: extra(:)      !! further periods, s, finite (any order; those
                                              !! outside [0.2 T1, 2 T1] are dropped)
        real(dp), intent(out) :: periods(:)   !! the grid, s, ascending in periods(1:n)
        integer, intent(out) :: n             !! number of periods used
        integer, intent(out) :: stat          !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: t_low, t_high, last, next, t
        real(dp) :: ext(size(extra))
        integer :: i, j, k, n_ext
        logical :: found
        periods = 0.0_dp
        n = 0
        call check_t1(t1, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (n_points < 2) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n_points = '// &
                           int_str(n_points)//': at least 2 periods are needed')
            return
        end if
        if (size(periods) < n_points + size(extra)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods: has room for '// &
                           int_str(size(periods))//' values; n_points + size(extra) = '// &
                           int_str(n_points + size(extra))//' are needed')
            return
        end if
        do i = 1, size(extra)
            if (.not. ieee_is_finite(extra(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'extra('//int_str(i)// &
                               ') = '//real_str(extra(i))//': the period (s) must be finite')
                return
            end if
        end do
        t_low = low_factor*t1
        t_high = high_factor*t1
        ! the extras inside [t_low, t_high], ascending and without repeats: each step takes
        ! the least value above the last one taken (at most size(extra) steps)
        n_ext = 0
        last = -huge(1.0_dp)
        do k = 1, size(extra)
            found = .false.
            next = huge(1.0_dp)
            do i = 1, size(extra)
                if (extra(i) > last .and. extra(i) <= next .and. extra(i) >= t_low &
                    .and. extra(i) <= t_high) then
                    next = extra(i)
                    found = .true.
                end if
            end do
            if (.not. found) exit
            n_ext = n_ext + 1
            ext(n_ext) = next
            last = next
        end do
        ! merged with T_i = 0.2 T1 10^((i - 1)/(n_points - 1)), i = 1 .. n_points, both ends
        ! exact (doc/record-suites.md section 2); a value equal to the last one is dropped
        i = 1
        j = 1
        do while (i <= n_points .or. j <= n_ext)
            if (i == 1) then
                t = t_low
            else if (i < n_points) then
                t = t_low*10.0_dp**(real(i - 1, dp)/real(n_points - 1, dp))
            else
                t = t_high
            end if
            if (i > n_points) then
                next = ext(j)
                j = j + 1
            else if (j > n_ext) then
                next = t
                i = i + 1
            else if (ext(j) < t) then
                next = ext(j)
                j = j + 1
            else
                next = t
                i = i + 1
            end if
            if (n == 0) then
                n = 1
                periods(1) = next
            else if (next > periods(n)) then
                n = n + 1
                periods(n) = next
            end if
        end do
    end subroutine suite_check_periods

    !> EN 1998-1 3.2.3.1.2(4) for a suite of n_rec records on the check grid (doc/record-suites.md).
    !> mean(i) = sum_k psa(i, k)/n_rec; (b) pga_mean >= target_pga; (c) mean(i) >= 0.9 target(i)
    !> at every period of the grid; the scale factors (M.1)-(M.3). Both comparisons allow a
    !> relative suite_rtol for rounding.
    !> Optional outputs: ratio(i) = mean(i)/target(i); own_mean(i), the mean PSA of the suite
    !> with each record scaled by own_scale(k).
    pure subroutine ec8_suite_check(periods, psa, pga, target, target_pga, t1, fit, check, &
                                    own_scale, mean, stat, errmsg, min_records, ratio, own_mean)
        real(dp), intent(in) :: periods(:)     !! check grid, s, ascending, in [0.2 T1, 2 T1]
        real(dp), intent(in) :: psa(:, :)      !! (size(periods), n_rec) 5 % PSA, g, > 0
        real(dp), intent(in) :: pga(:)         !! (n_rec) peak ground accelerations, g, > 0
        real(dp), intent(in) :: target(:)      !! the code's elastic 5 % spectrum there, g, > 0
        real(dp), intent(in) :: target_pga     !! the code spectrum at T = 0 (a_g S), g, > 0
        real(dp), intent(in) :: t1             !! fundamental period T1, s, finite, > 0
        integer, intent(in) :: fit             !! SUITE_FIT_LINEAR (M.2) or SUITE_FIT_LOG (M.3)
        type(suite_check_t), intent(out) :: check   !! the outcome
        real(dp), intent(out) :: own_scale(:)  !! (n_rec) each record's own scale factor (-)
        real(dp), intent(out) :: mean(:)       !! (size(periods)) mean PSA of the suite, g
        integer, intent(out) :: stat           !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        !> fewer records are refused; >= 1, default 3 (the code's rule (a))
        integer, intent(in), optional :: min_records
        real(dp), intent(out), optional :: ratio(:)     !! (size(periods)) mean/target (-)
        real(dp), intent(out), optional :: own_mean(:)  !! (size(periods)) scaled mean PSA, g
        real(dp) :: rel(size(periods)), scaled(size(periods))
        real(dp) :: top, need, own_pga
        logical :: own_pga_ok, own_spectrum_ok
        integer :: n, n_rec, i, k, i_min
        n = size(periods)
        n_rec = size(pga)
        own_scale = 0.0_dp
        mean = 0.0_dp
        if (present(ratio)) ratio = 0.0_dp
        if (present(own_mean)) own_mean = 0.0_dp
        call check_inputs(periods, psa, pga, target, target_pga, t1, fit, size(own_scale), &
                          size(mean), optval(min_records, code_min_records), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (present(ratio)) then
            if (size(ratio) /= n) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ratio: must have the '// &
                               'size of periods ('//int_str(n)//')')
                return
            end if
        end if
        if (present(own_mean)) then
            if (size(own_mean) /= n) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'own_mean: must have '// &
                               'the size of periods ('//int_str(n)//')')
                return
            end if
        end if

        check%n_records = n_rec
        check%t1 = t1
        check%t_low = low_factor*t1
        check%t_high = high_factor*t1
        check%count_ok = n_rec >= code_min_records                       ! (a)
        check%mean_allowed = n_rec >= mean_records                       ! 4.3.3.4.3(3)

        ! the unscaled suite
        do i = 1, n
            mean(i) = sum(psa(i, :))/real(n_rec, dp)
        end do
        check%pga_mean = sum(pga)/real(n_rec, dp)
        check%pga_target = target_pga
        call judge(mean, check%pga_mean, check%pga_ratio, check%pga_ok, check%min_ratio, &
                   i_min, check%spectrum_ok)
        check%t_min_ratio = periods(i_min)
        check%passed = check%count_ok .and. check%pga_ok .and. check%spectrum_ok
        if (present(ratio)) ratio = mean/target

        ! (M.1) common_scale = max(target_pga/pga_mean, max_i 0.9 target(i)/mean(i))
        need = target_pga/check%pga_mean
        do i = 1, n
            need = max(need, spectrum_fraction*target(i)/mean(i))
        end do
        check%common_scale = need

        ! each record's own factor, then the suite so scaled
        do k = 1, n_rec
            if (fit == SUITE_FIT_LINEAR) then
                ! (M.2) s_k = sum_i psa_ik target_i / sum_i psa_ik^2, numerator and
                ! denominator divided by top^2, top = max_i psa_ik (no overflow)
                top = maxval(psa(:, k))
                rel = psa(:, k)/top
                own_scale(k) = sum(rel*(target/top))/sum(rel**2)
            else
                ! (M.3) s_k = exp(mean_i (ln target_i - ln psa_ik))
                own_scale(k) = exp(sum(log(target) - log(psa(:, k)))/real(n, dp))
            end if
        end do
        scaled = 0.0_dp
        own_pga = 0.0_dp
        do k = 1, n_rec
            scaled = scaled + own_scale(k)*psa(:, k)
            own_pga = own_pga + own_scale(k)*pga(k)
        end do
        scaled = scaled/real(n_rec, dp)
        own_pga = own_pga/real(n_rec, dp)
        call judge(scaled, own_pga, check%own_pga_ratio, own_pga_ok, check%own_min_ratio, &
                   i_min, own_spectrum_ok)
        check%own_t_min_ratio = periods(i_min)
        check%own_passed = check%count_ok .and. own_pga_ok .and. own_spectrum_ok
        if (present(own_mean)) own_mean = scaled

    contains

        !> (b) and (c) for the mean spectrum m and mean PGA p of a suite: the ratios to the
        !> target, the first period of the least ratio, and the two verdicts.
        pure subroutine judge(m, p, p_ratio, p_ok, m_ratio, at, m_ok)
            real(dp), intent(in) :: m(:), p
            real(dp), intent(out) :: p_ratio, m_ratio
            logical, intent(out) :: p_ok, m_ok
            integer, intent(out) :: at
            integer :: j
            real(dp) :: r
            p_ratio = p/target_pga
            p_ok = p >= target_pga*(1.0_dp - suite_rtol)                         ! (b)
            m_ok = .true.
            at = 1
            m_ratio = m(1)/target(1)
            do j = 1, n
                m_ok = m_ok .and. m(j) >= spectrum_fraction*target(j)*(1.0_dp - suite_rtol) ! (c)
                r = m(j)/target(j)
                if (r < m_ratio) then
                    m_ratio = r
                    at = j
                end if
            end do
        end subroutine judge

    end subroutine ec8_suite_check

    !> T1 finite and > 0.
    pure subroutine check_t1(t1, stat, errmsg)
        real(dp), intent(in) :: t1
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(t1)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't1 = '//real_str(t1)// &
                           ': the fundamental period T1 (s) must be finite and > 0')
        end if
    end subroutine check_t1

    !> Every input of ec8_suite_check: T1, fit, counts, sizes, the grid, positive spectra.
    pure subroutine check_inputs(periods, psa, pga, target, target_pga, t1, fit, n_scale, &
                                 n_mean, min_records, stat, errmsg)
        real(dp), intent(in) :: periods(:), psa(:, :), pga(:), target(:), target_pga, t1
        integer, intent(in) :: fit, n_scale, n_mean, min_records
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: n, n_rec, i, k
        real(dp) :: low, high
        n = size(periods)
        n_rec = size(pga)
        call check_t1(t1, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (fit /= SUITE_FIT_LINEAR .and. fit /= SUITE_FIT_LOG) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'fit = '//int_str(fit)// &
                           ': must be SUITE_FIT_LINEAR (1) or SUITE_FIT_LOG (2)')
            return
        end if
        if (min_records < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'min_records = '// &
                           int_str(min_records)//': must be >= 1')
            return
        end if
        if (n_rec < min_records) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n = '//int_str(n_rec)// &
                           ' records: the suite needs at least '//int_str(min_records)// &
                           ' (EN 1998-1 3.2.3.1.2(4)a: at least 3)')
            return
        end if
        if (n < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'periods: the check grid is empty')
            return
        end if
        if (size(psa, 1) /= n .or. size(psa, 2) /= n_rec) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'psa: must have shape ('// &
                           int_str(n)//', '//int_str(n_rec)//') (periods, records), got ('// &
                           int_str(size(psa, 1))//', '//int_str(size(psa, 2))//')')
            return
        end if
        if (size(target) /= n .or. n_mean /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target, mean: must have '// &
                           'the size of periods ('//int_str(n)//')')
            return
        end if
        if (n_scale /= n_rec) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'own_scale: must have the '// &
                           'size of pga ('//int_str(n_rec)//', one per record)')
            return
        end if
        low = low_factor*t1*(1.0_dp - range_rtol)
        high = high_factor*t1*(1.0_dp + range_rtol)
        do i = 1, n
            if (.not. ieee_is_finite(periods(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('//int_str(i)// &
                               ') = '//real_str(periods(i))//': the period (s) must be finite')
                return
            end if
            if (periods(i) < low .or. periods(i) > high) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('//int_str(i)// &
                               ') = '//real_str(periods(i))//': must lie in [0.2 T1, 2 T1] = ['// &
                               real_str(low_factor*t1)//', '//real_str(high_factor*t1)//'] s')
                return
            end if
            if (i > 1 .and. .not. periods(max(i - 1, 1)) < periods(i)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('// &
                               int_str(i)//') = '//real_str(periods(i))// &
                               ': the periods must be strictly ascending')
                return
            end if
            if (.not. finite_positive(target(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target('//int_str(i)// &
                               ') = '//real_str(target(i))//': the target spectrum (g) at T = '// &
                               real_str(periods(i))//' s must be finite and > 0')
                return
            end if
        end do
        if (.not. finite_positive(target_pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target_pga = '// &
                           real_str(target_pga)//': the target at T = 0 (a_g S, g) must be '// &
                           'finite and > 0')
            return
        end if
        do k = 1, n_rec
            if (.not. finite_positive(pga(k))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga('//int_str(k)// &
                               ') = '//real_str(pga(k))//': the PGA (g) of record '// &
                               int_str(k)//' must be finite and > 0')
                return
            end if
            do i = 1, n
                if (.not. finite_positive(psa(i, k))) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'psa('// &
                                   int_str(i)//', '//int_str(k)//') = '//real_str(psa(i, k))// &
                                   ': the 5 % PSA (g) of record '//int_str(k)//' at T = '// &
                                   real_str(periods(i))//' s must be finite and > 0 (a record '// &
                                   'with zero PSA cannot be scaled)')
                    return
                end if
            end do
        end do
    end subroutine check_inputs

end module seispulse_record_suite
