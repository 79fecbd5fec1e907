!> EN 1998-1 3.2.3.1.2(4) check of a suite of recorded accelerograms (admitted by
!> 3.2.3.1.3; its paragraph not verified) against the code's elastic spectrum
!> (doc/record-suites.md).
!>
!> The rules: (a) at least 3 records; (b) the mean of the records' zero-period spectral
!> accelerations (their PGA) is not below a_g S, the elastic spectrum at T = 0; (c) over
!> [0.2 T1, 2 T1] (T1: the structure's fundamental period) no value of the mean 5 %-damped
!> elastic spectrum of the suite lies below 90 % of the code's elastic spectrum.
!> EN 1998-1 4.3.3.4.3(3): with at least 7 records the mean response should be used (else
!> the most unfavourable one), reported as `mean_allowed`.
!>
!> `ec8_suite_check` works on arrays: the caller gives the check grid
!> (`suite_check_periods`), each record's 5 % pseudo-spectral acceleration (PSA) and PGA
!> there and the target spectrum. Besides the check it gives the smallest common scale
!> factor that makes the suite pass (M.1) and one scale factor per record fitted to the
!> target over the grid, linear (M.2) or in log space (M.3).
!>
!> Comparisons are made up to rounding: a value passes when it is not below its limit by
!> more than `suite_rtol` (relative), so that a suite scaled by `common_scale` passes.
!>
!> `ec8_suite_check_records` is the whole check from the records: the target is a code
!> spectrum the library evaluates at any period (`suite_target_t`: the EN 1998-1 or the
!> EAK 2000 elastic 5 % spectrum), the records' 5 % PSA is computed here, and rule (c)
!> is checked between the grid periods too: the least ratios of the grid are refined by
!> Brent's minimisation (doc/record-suites.md section 2).
module seispulse_record_suite
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: finite_positive
    use seispulse_optval, only: optval
    use seispulse_format, only: real_str, int_str
    use seispulse_roots, only: scalar_function, find_minimum
    use seispulse_records, only: STANDARD_GRAVITY
    use seispulse_sdof_sim, only: sdof_spectrum, pseudo_spectra, SDOF_PEAKS_EXACT
    use seispulse_codes, only: ec8_elastic_spectrum, ec8_ground_parameters, &
                               EC8_SPECTRUM_TYPE_1, EC8_GROUND_A
    use seispulse_eak2000, only: eak2000_elastic_spectrum, eak2000_ground_parameters, &
                                 EAK_GROUND_B
    implicit none
    private

    public :: SUITE_FIT_LINEAR, SUITE_FIT_LOG, suite_rtol, suite_check_t
    public :: suite_check_periods, ec8_suite_check
    public :: SUITE_TARGET_EC8, SUITE_TARGET_EAK, SUITE_RULE_PGA, SUITE_RULE_SPECTRUM
    public :: suite_target_t, suite_target_values, suite_target_pga, suite_target_corners
    public :: suite_refine_margin, suite_refine_spacings, suite_records_room
    public :: ec8_suite_check_records, suite_records_grid, SUITE_SPECTRUM_FRACTION

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
    real(dp), parameter :: low_factor = 0.2_dp, high_factor = 2.0_dp
    !> Rule (c): the mean spectrum of the suite is not below this fraction of the target
    !> (EN 1998-1 3.2.3.1.2(4)c: 90 %) (-).
    real(dp), parameter :: SUITE_SPECTRUM_FRACTION = 0.9_dp

    !> The target spectrum of ec8_suite_check_records: EN 1998-1 (3.2)-(3.5) or EAK 2000
    !> (K.1)-(K.3) with q = theta = 1 (the elastic spectrum), both at 5 % damping.
    integer, parameter :: SUITE_TARGET_EC8 = 1
    integer, parameter :: SUITE_TARGET_EAK = 2
    !> The rule that sets common_scale (M.1): (b) the PGA or (c) the spectrum.
    integer, parameter :: SUITE_RULE_PGA = 1
    integer, parameter :: SUITE_RULE_SPECTRUM = 2
    !> Grid intervals searched for the least ratio between grid periods: those whose smaller
    !> end ratio is within a margin (relative) of the least ratio on the grid, and the two
    !> intervals next to every local minimum of the grid within twice the margin. The
    !> margin is suite_refine_spacings times the grid's relative spacing
    !> 10^(1/(n_points - 1)) - 1, at least suite_refine_margin (doc/record-suites.md
    !> section 2: 0.58 % at 400 points, 4.8 % at 50; the misses measured on the grid alone
    !> were at most 0.7 spacings).
    real(dp), parameter :: suite_refine_margin = 0.005_dp
    real(dp), parameter :: suite_refine_spacings = 1.0_dp
    !> Damping ratio of the records' spectra and of the target (the code's 5 %).
    real(dp), parameter :: suite_damping = 0.05_dp
    !> Periods a refinement may add to the grid (the least ratio of the suite and of the
    !> own-scaled suite), and the most extras the records routine adds (T1 and 3 corners).
    integer, parameter :: refined_room = 2, own_extras = 4

    !> A code's elastic 5 % spectrum that the check evaluates at any period (g).
    type :: suite_target_t
        integer :: code = SUITE_TARGET_EC8      !! SUITE_TARGET_EC8 or SUITE_TARGET_EAK
        integer :: spectrum_type = EC8_SPECTRUM_TYPE_1  !! EN 1998-1 type 1 or 2 (EC8)
        real(dp) :: ag = 0.0_dp                 !! design ground acceleration a_g, g (EC8), > 0
        integer :: ground = EC8_GROUND_A        !! EC8_GROUND_A..E or EAK_GROUND_A..D
        real(dp) :: alpha = 0.0_dp              !! A/g (EAK), > 0
        real(dp) :: importance = 1.0_dp         !! gamma_I (EAK), > 0
        real(dp) :: eta_min = 0.0_dp            !! lower limit of eta (EAK), [0, 1]
        real(dp) :: exponent = 2.0_dp/3.0_dp    !! long-period exponent of Phi_e (EAK), > 0
    end type suite_target_t

    !> The ratio to the target of a weighted mean of the records' 5 % PSA at one period:
    !> sum_k w_k PSA_k(T) / n_rec / target(T); one evaluation is the PSA of every record.
    type, extends(scalar_function) :: suite_ratio_t
        real(dp), pointer :: accel(:) => null()   !! the records, concatenated, g
        integer, allocatable :: first(:), npts(:)
        real(dp), allocatable :: dt(:), weight(:)
        type(suite_target_t) :: target
        integer :: stat = SEISPULSE_SUCCESS       !! first failure of an evaluation
        character(len=512) :: msg = ''
    contains
        procedure :: eval => suite_ratio_eval
    end type suite_ratio_t

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
        !> the rule that sets common_scale: SUITE_RULE_PGA ((b)) or SUITE_RULE_SPECTRUM ((c))
        integer :: scale_rule = 0
        !> least mean/target and own-scaled mean/target at the grid periods only, before the
        !> refinement of ec8_suite_check_records (equal to min_ratio, own_min_ratio from
        !> ec8_suite_check) (-)
        real(dp) :: grid_min_ratio = 0.0_dp
        real(dp) :: grid_own_min_ratio = 0.0_dp
        integer :: n_searched = 0             !! grid intervals searched by the refinement
        !> periods of the check grid, without the refined minima that
        !> ec8_suite_check_records adds to its returned grid
        integer :: n_grid = 0
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
        check%n_grid = n
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
        check%scale_rule = SUITE_RULE_PGA
        do i = 1, n
            if (SUITE_SPECTRUM_FRACTION*target(i)/mean(i) > need) check%scale_rule = SUITE_RULE_SPECTRUM
            need = max(need, SUITE_SPECTRUM_FRACTION*target(i)/mean(i))
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
        check%grid_min_ratio = check%min_ratio
        check%grid_own_min_ratio = check%own_min_ratio

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
                m_ok = m_ok .and. m(j) >= SUITE_SPECTRUM_FRACTION*target(j)*(1.0_dp - suite_rtol) ! (c)
                r = m(j)/target(j)
                if (r < m_ratio) then
                    m_ratio = r
                    at = j
                end if
            end do
        end subroutine judge

    end subroutine ec8_suite_check

    ! ------------------------------------------------------------------------------
    ! The target spectrum
    ! ------------------------------------------------------------------------------

    !> The target's elastic 5 % spectrum at periods(:) (s, finite, >= 0), g: EN 1998-1
    !> (3.2)-(3.5) (seispulse_codes ec8_elastic_spectrum) or EAK 2000 Phi_e (K.1)-(K.3)
    !> with q = theta = 1 (seispulse_eak2000 eak2000_elastic_spectrum). The acceleration
    !> (ag or alpha) must be > 0: a zero target cannot be checked against.
    pure subroutine suite_target_values(target, periods, values, stat, errmsg)
        type(suite_target_t), intent(in) :: target  !! the code spectrum
        real(dp), intent(in) :: periods(:)          !! periods T, s
        real(dp), intent(out) :: values(:)          !! the spectrum there, g (size of periods)
        integer, intent(out) :: stat                !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        values = 0.0_dp
        select case (target%code)
        case (SUITE_TARGET_EC8)
            call positive_target('ag', target%ag, 'the design ground acceleration of the '// &
                                 'target (g)', stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call ec8_elastic_spectrum(periods, target%ag, target%spectrum_type, target%ground, &
                                      100.0_dp*suite_damping, values, stat, errmsg)
        case (SUITE_TARGET_EAK)
            call positive_target('alpha', target%alpha, 'the ground acceleration A/g of the '// &
                                 'target', stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            call eak2000_elastic_spectrum(periods, target%alpha, target%ground, &
                                          target%importance, 100.0_dp*suite_damping, &
                                          target%eta_min, target%exponent, values, stat, errmsg)
        case default
            call refuse_code(target%code, stat, errmsg)
        end select
    end subroutine suite_target_values

    !> The refusal of an unknown target code.
    pure subroutine refuse_code(code, stat, errmsg)
        integer, intent(in) :: code
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'code = '//int_str(code)// &
                       ': must be SUITE_TARGET_EC8 (1) or SUITE_TARGET_EAK (2)')
    end subroutine refuse_code

    !> The target's acceleration `name` = x must be finite and > 0 (what: its meaning).
    pure subroutine positive_target(name, x, what, stat, errmsg)
        character(len=*), intent(in) :: name, what
        real(dp), intent(in) :: x
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(x)) call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
            name//' = '//real_str(x)//': '//what//' must be finite and > 0')
    end subroutine positive_target

    !> The target at T = 0, the PGA target of rule (b), g: a_g S (EN 1998-1) or
    !> gamma_I A (EAK 2000).
    pure subroutine suite_target_pga(target, pga, stat, errmsg)
        type(suite_target_t), intent(in) :: target  !! the code spectrum
        real(dp), intent(out) :: pga                !! its value at T = 0, g
        integer, intent(out) :: stat                !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: v(1)
        call suite_target_values(target, [0.0_dp], v, stat, errmsg)
        pga = v(1)
    end subroutine suite_target_pga

    !> The corner periods of the target (s): TB, TC, TD (EN 1998-1 Table 3.2/3.3) or T1, T2
    !> (EAK 2000); corners(n+1:) = 0. corners(:) needs room for 3.
    pure subroutine suite_target_corners(target, corners, n, stat, errmsg)
        type(suite_target_t), intent(in) :: target  !! the code spectrum
        real(dp), intent(out) :: corners(:)         !! corner periods, s, ascending
        integer, intent(out) :: n                   !! number of corners (3 EC8, 2 EAK)
        integer, intent(out) :: stat                !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: s, tb, tc, td
        corners = 0.0_dp
        n = 0
        if (size(corners) < 3) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'corners: has room for '// &
                           int_str(size(corners))//' values; 3 are needed')
            return
        end if
        select case (target%code)
        case (SUITE_TARGET_EC8)
            call ec8_ground_parameters(target%spectrum_type, target%ground, s, tb, tc, td, &
                                       stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) then
                n = 3
                corners(1:3) = [tb, tc, td]
            end if
        case (SUITE_TARGET_EAK)
            call eak2000_ground_parameters(target%ground, tb, tc, stat, errmsg)
            if (stat == SEISPULSE_SUCCESS) then
                n = 2
                corners(1:2) = [tb, tc]
            end if
        case default
            call refuse_code(target%code, stat, errmsg)
        end select
    end subroutine suite_target_corners

    !> Room that ec8_suite_check_records needs in its period arrays for n_points and
    !> n_extra extra periods: the grid, T1, the target's corners and the refined minima.
    pure integer function suite_records_room(n_points, n_extra) result(room)
        integer, intent(in) :: n_points  !! log-spaced periods of the grid
        integer, intent(in) :: n_extra   !! the caller's extra periods
        room = max(n_points, 0) + max(n_extra, 0) + own_extras + refined_room
    end function suite_records_room

    !> The check grid of ec8_suite_check_records: suite_check_periods(t1, n_points,
    !> [extra, T1, the target's corners]) (doc/record-suites.md section 2); periods(:) needs
    !> room for n_points + size(extra) + 4 (suite_records_room is enough); periods(n+1:) = 0.
    pure subroutine suite_records_grid(target, t1, n_points, extra, periods, n, stat, errmsg)
        type(suite_target_t), intent(in) :: target  !! the code spectrum (its corners)
        real(dp), intent(in) :: t1           !! fundamental period T1, s, finite, > 0
        integer, intent(in) :: n_points      !! log-spaced periods, >= 2
        real(dp), intent(in) :: extra(:)     !! further periods, s, finite (outside dropped)
        real(dp), intent(out) :: periods(:)  !! the grid, s, ascending in periods(1:n)
        integer, intent(out) :: n            !! number of periods used
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        real(dp) :: corners(3)
        integer :: nc
        periods = 0.0_dp
        n = 0
        call suite_target_corners(target, corners, nc, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call suite_check_periods(t1, n_points, [extra, t1, corners(1:nc)], periods, n, stat, &
                                 errmsg)
    end subroutine suite_records_grid

    ! ------------------------------------------------------------------------------
    ! The check from the records
    ! ------------------------------------------------------------------------------

    !> EN 1998-1 3.2.3.1.2(4) for records given as samples (doc/record-suites.md section 2).
    !> The check grid is suite_records_grid(target, t1, n_points, extra): suite_check_periods
    !> with [extra, T1, the target's corners];
    !> each record's 5 % PSA there (sdof_spectrum, exact peaks, and pseudo_spectra) and PGA
    !> (max |accel|); ec8_suite_check on the grid. Then rule (c) between the grid periods:
    !> for the suite and for the suite scaled by own_scale, every grid interval whose smaller
    !> end ratio is within suite_refine_margin (relative) of the least ratio on the grid,
    !> and both intervals next to every local minimum of the ratio on the grid, are searched
    !> with find_minimum (Brent; one evaluation = the PSA of every record at one period).
    !> min_ratio, t_min_ratio, spectrum_ok, passed, common_scale (M.1), scale_rule,
    !> own_min_ratio, own_t_min_ratio and own_passed are taken from the refined minima; the
    !> grid values stay in grid_min_ratio, grid_own_min_ratio. The refined minimisers are
    !> added to the returned grid with their spectra. own_scale is fitted (M.2)/(M.3) on the
    !> check grid without the refined periods. A trough narrower than the grid spacing both
    !> of whose grid neighbours lie more than the margin above the least grid ratio, away
    !> from a local minimum of the grid, can still be missed.
    !> On a refusal that concerns one record (a bad sample or step, a PGA or PSA of 0),
    !> bad_record gives its index (else 0).
    subroutine ec8_suite_check_records(accel, first, npts, dt, target, t1, fit, check, &
                                       periods, n_periods, psa, pga, target_psa, mean, ratio, &
                                       own_mean, own_scale, stat, errmsg, n_points, extra, &
                                       min_records, bad_record, margin)
        real(dp), intent(in), target :: accel(:)   !! the records concatenated, g
        integer, intent(in) :: first(:)      !! (n_rec) index in accel of each record's first sample
        integer, intent(in) :: npts(:)       !! (n_rec) samples of each record, >= 1
        real(dp), intent(in) :: dt(:)        !! (n_rec) time step of each record, s, > 0
        type(suite_target_t), intent(in) :: target  !! the code's elastic 5 % spectrum
        real(dp), intent(in) :: t1           !! fundamental period T1, s, finite, > 0
        integer, intent(in) :: fit           !! SUITE_FIT_LINEAR (M.2) or SUITE_FIT_LOG (M.3)
        type(suite_check_t), intent(out) :: check  !! the outcome
        !> the check grid with the refined minima, s, ascending in periods(1:n_periods); room
        !> for suite_records_room(n_points, size(extra))
        real(dp), intent(out) :: periods(:)
        integer, intent(out) :: n_periods    !! periods used
        real(dp), intent(out) :: psa(:, :)   !! (room, n_rec) 5 % PSA of each record, g
        real(dp), intent(out) :: pga(:)      !! (n_rec) PGA of each record, g
        real(dp), intent(out) :: target_psa(:)  !! (room) the target there, g
        real(dp), intent(out) :: mean(:)     !! (room) mean PSA of the suite, g
        real(dp), intent(out) :: ratio(:)    !! (room) mean/target (-)
        real(dp), intent(out) :: own_mean(:) !! (room) mean PSA of the records x own_scale, g
        real(dp), intent(out) :: own_scale(:)  !! (n_rec) each record's own factor (-)
        integer, intent(out) :: stat         !! SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT or
                                             !! the error of a spectrum
        character(len=*), intent(inout), optional :: errmsg  !! message naming the parameter
        integer, intent(in), optional :: n_points  !! log-spaced grid periods, >= 2; default 400
        !> further periods, s (those inside the range kept); default none
        real(dp), intent(in), optional :: extra(:)
        integer, intent(in), optional :: min_records  !! fewer are refused; default 3
        integer, intent(out), optional :: bad_record  !! the record a refusal concerns, or 0
        !> the refinement margin (relative, >= 0); default max(suite_refine_margin,
        !> suite_refine_spacings x the grid's relative spacing)
        real(dp), intent(in), optional :: margin
        real(dp), allocatable :: ext(:), grid(:), spec(:, :), tgt(:), m0(:), r0(:), om0(:)
        real(dp) :: target_pga, row(size(pga)), t_best(2), r_best(2), tgt1(1), add(2)
        type(suite_ratio_t) :: f
        integer :: n_rec, np_in, room, n0, k, i, j, n_min, bad, na, ia, st
        real(dp) :: band
        character(len=512) :: msg

        n_rec = size(first)
        np_in = optval(n_points, 400)
        n_periods = 0
        periods = 0.0_dp
        psa = 0.0_dp
        pga = 0.0_dp
        target_psa = 0.0_dp
        mean = 0.0_dp
        ratio = 0.0_dp
        own_mean = 0.0_dp
        own_scale = 0.0_dp
        bad = 0
        if (present(bad_record)) bad_record = 0
        n_min = optval(min_records, code_min_records)
        band = max(suite_refine_margin, suite_refine_spacings* &
                   (10.0_dp**(1.0_dp/real(max(np_in - 1, 1), dp)) - 1.0_dp))
        if (present(margin)) band = margin
        if (present(extra)) then
            ext = extra
        else
            allocate(ext(0))
        end if
        room = suite_records_room(np_in, size(ext))
        ! --- the inputs
        call check_t1(t1, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (size(npts) /= n_rec .or. size(dt) /= n_rec .or. size(pga) /= n_rec &
            .or. size(own_scale) /= n_rec) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'first, npts, dt, pga, '// &
                           'own_scale: need one value per record ('//int_str(n_rec)//')')
            return
        end if
        if (size(periods) < room .or. size(target_psa) < room .or. size(mean) < room .or. &
            size(ratio) < room .or. size(own_mean) < room .or. size(psa, 1) < room .or. &
            size(psa, 2) /= n_rec) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods, psa, target_psa,'// &
                           ' mean, ratio, own_mean: need room for '//int_str(room)// &
                           ' periods (suite_records_room) and psa one column per record')
            return
        end if
        if (.not. (band >= 0.0_dp .and. ieee_is_finite(band))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'margin = '// &
                           real_str(band)//': the refinement margin must be finite and >= 0')
            return
        end if
        call check_count(n_rec, n_min, 'records: '//int_str(n_rec)//' given;', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do k = 1, n_rec
            if (first(k) < 1 .or. npts(k) < 1 .or. first(k) > size(accel) - npts(k) + 1) then
                bad = k
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'record '//int_str(k)// &
                               ': first = '//int_str(first(k))//', npts = '//int_str(npts(k))// &
                               ': the samples must lie in accel (1..'//int_str(size(accel))//')')
                call give_bad()
                return
            end if
        end do
        call suite_target_pga(target, target_pga, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return

        ! --- the grid, the target and the spectra there
        allocate(grid(np_in + size(ext) + own_extras))
        call suite_records_grid(target, t1, np_in, ext, grid, n0, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        allocate(tgt(n0), spec(n0, n_rec), m0(n0), r0(n0), om0(n0))
        call suite_target_values(target, grid(1:n0), tgt, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do k = 1, n_rec
            call record_spectrum(k, grid(1:n0), spec(:, k), pga(k), stat, msg)
            if (stat /= SEISPULSE_SUCCESS) then
                bad = k
                st = stat
                call set_error(stat, errmsg, st, 'record '//int_str(k)//': '//trim(msg))
                call give_bad()
                return
            end if
            if (.not. pga(k) > 0.0_dp) then
                bad = k
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'record '//int_str(k)// &
                               ': its PGA is '//real_str(pga(k))//' g; a record with zero '// &
                               'PGA cannot be scaled')
                call give_bad()
                return
            end if
            do i = 1, n0
                if (.not. spec(i, k) > 0.0_dp) then
                    bad = k
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'record '// &
                                   int_str(k)//': its 5 % PSA at T = '//real_str(grid(i))// &
                                   ' s is '//real_str(spec(i, k))//' g; a record with zero '// &
                                   'PSA cannot be scaled')
                    call give_bad()
                    return
                end if
            end do
        end do
        call ec8_suite_check(grid(1:n0), spec, pga, tgt, target_pga, t1, fit, check, own_scale, &
                             m0, stat, errmsg, min_records=n_min, ratio=r0, own_mean=om0)
        if (stat /= SEISPULSE_SUCCESS) return

        ! --- rule (c) between the grid periods: the suite (weights 1), then the suite
        ! scaled by own_scale (its grid ratio om0/tgt)
        f%accel => accel
        f%first = first
        f%npts = npts
        f%dt = dt
        f%target = target
        f%weight = [(1.0_dp, k = 1, n_rec)]
        call refine(r0, check%min_ratio, check%t_min_ratio, r_best(1), t_best(1))
        if (stat /= SEISPULSE_SUCCESS) return
        f%weight = own_scale
        call refine(om0/tgt, check%own_min_ratio, check%own_t_min_ratio, r_best(2), t_best(2))
        if (stat /= SEISPULSE_SUCCESS) return
        if (r_best(1) < check%min_ratio) then
            check%min_ratio = r_best(1)
            check%t_min_ratio = t_best(1)
            check%spectrum_ok = check%min_ratio >= SUITE_SPECTRUM_FRACTION*(1.0_dp - suite_rtol) ! (c)
            check%passed = check%passed .and. check%spectrum_ok
            if (SUITE_SPECTRUM_FRACTION/check%min_ratio > check%common_scale) then      ! (M.1)
                check%common_scale = SUITE_SPECTRUM_FRACTION/check%min_ratio
                check%scale_rule = SUITE_RULE_SPECTRUM
            end if
        end if
        if (r_best(2) < check%own_min_ratio) then
            check%own_min_ratio = r_best(2)
            check%own_t_min_ratio = t_best(2)
            check%own_passed = check%own_passed .and. &
                check%own_min_ratio >= SUITE_SPECTRUM_FRACTION*(1.0_dp - suite_rtol)
        end if

        ! --- the returned grid: the check grid with the refined minimisers (those below the
        ! grid's least ratio lie strictly inside a grid interval), ascending
        na = 0
        do k = 1, 2
            if (r_best(k) < merge(check%grid_min_ratio, check%grid_own_min_ratio, k == 1)) then
                if (na == 1) then
                    if (.not. (t_best(k) < add(1) .or. t_best(k) > add(1))) cycle
                end if
                na = na + 1
                add(na) = t_best(k)
            end if
        end do
        if (na == 2) then
            if (add(2) < add(1)) add = [add(2), add(1)]
        end if
        j = 0
        ia = 1
        do i = 1, n0
            do while (ia <= na)
                if (.not. add(ia) < grid(i)) exit
                call put_refined(add(ia))
                if (stat /= SEISPULSE_SUCCESS) return
                ia = ia + 1
            end do
            j = j + 1
            periods(j) = grid(i)
            psa(j, :) = spec(i, :)
            target_psa(j) = tgt(i)
            mean(j) = m0(i)
            ratio(j) = r0(i)
            own_mean(j) = om0(i)
        end do
        n_periods = j

    contains

        !> The spectrum of record k at the periods p: 5 % PSA (g) and its PGA (g).
        subroutine record_spectrum(k, p, out, peak, st, msg)
            integer, intent(in) :: k
            real(dp), intent(in) :: p(:)
            real(dp), intent(out) :: out(:), peak
            integer, intent(out) :: st
            character(len=*), intent(inout) :: msg
            real(dp) :: sd(size(p) + 1, 1), sv(size(p) + 1, 1), sa(size(p) + 1, 1), &
                        psv(size(p) + 1, 1), ps(size(p) + 1, 1)
            out = 0.0_dp
            peak = 0.0_dp
            call sdof_spectrum(accel(first(k):first(k) + npts(k) - 1), dt(k), [0.0_dp, p], &
                               [suite_damping], STANDARD_GRAVITY, sd, sv, sa, st, msg, &
                               peaks=SDOF_PEAKS_EXACT)
            if (st /= SEISPULSE_SUCCESS) return
            peak = sa(1, 1)
            call pseudo_spectra([0.0_dp, p], sd, STANDARD_GRAVITY, peak, psv, ps)
            out = ps(2:, 1)
        end subroutine record_spectrum

        !> The least of f over the check grid (r_grid the grid ratios; r_min at t_min the
        !> grid's least): Brent on the intervals chosen as documented above; r_out, t_out
        !> the least found (r_min, t_min if none is lower).
        subroutine refine(r_grid, r_min, t_min, r_out, t_out)
            real(dp), intent(in) :: r_grid(:), r_min, t_min
            real(dp), intent(out) :: r_out, t_out
            real(dp) :: x, fx, lo
            integer :: i, st
            logical :: search
            r_out = r_min
            t_out = t_min
            do i = 1, n0 - 1
                lo = min(r_grid(i), r_grid(i + 1))
                search = lo <= r_min*(1.0_dp + band)
                search = search .or. (lo <= r_min*(1.0_dp + 2.0_dp*band) .and. &
                                      (local_min(r_grid, i) .or. local_min(r_grid, i + 1)))
                if (.not. search) cycle
                check%n_searched = check%n_searched + 1
                call find_minimum(f, grid(i), grid(i + 1), x, fx, st)
                if (f%stat /= SEISPULSE_SUCCESS) then
                    call set_error(stat, errmsg, f%stat, trim(f%msg))
                    return
                end if
                ! SEISPULSE_NO_CONVERGENCE keeps the best point found (a true value of f)
                if (fx < r_out) then
                    r_out = fx
                    t_out = x
                end if
            end do
        end subroutine refine

        !> Whether grid point i is a local minimum of r (at an end: below its neighbour).
        pure logical function local_min(r, i)
            real(dp), intent(in) :: r(:)
            integer, intent(in) :: i
            local_min = .true.
            if (i > 1) local_min = r(i) < r(i - 1)
            if (i < size(r)) local_min = local_min .and. r(i) < r(i + 1)
        end function local_min

        !> Add the period t (its spectra, the target, mean, ratio, own mean) at j + 1.
        subroutine put_refined(t)
            real(dp), intent(in) :: t
            real(dp) :: peak_k, one(1)
            integer :: kk, st
            do kk = 1, n_rec
                call record_spectrum(kk, [t], one, peak_k, stat, msg)
                if (stat /= SEISPULSE_SUCCESS) then
                    st = stat
                    call set_error(stat, errmsg, st, 'record '//int_str(kk)//': '//trim(msg))
                    return
                end if
                row(kk) = one(1)
            end do
            call suite_target_values(target, [t], tgt1, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            j = j + 1
            periods(j) = t
            psa(j, :) = row
            target_psa(j) = tgt1(1)
            mean(j) = 0.0_dp
            own_mean(j) = 0.0_dp
            do kk = 1, n_rec      ! summed in the order of suite_ratio_eval
                mean(j) = mean(j) + row(kk)
                own_mean(j) = own_mean(j) + own_scale(kk)*row(kk)
            end do
            mean(j) = mean(j)/real(n_rec, dp)
            own_mean(j) = own_mean(j)/real(n_rec, dp)
            ratio(j) = mean(j)/tgt1(1)
        end subroutine put_refined

        subroutine give_bad()
            if (present(bad_record)) bad_record = bad
        end subroutine give_bad

    end subroutine ec8_suite_check_records

    !> f(T) = sum_k w_k PSA_k(T) / n_rec / target(T) (-); NaN (and self%stat, self%msg) when
    !> a spectrum fails.
    function suite_ratio_eval(self, x) result(y)
        class(suite_ratio_t), intent(inout) :: self
        real(dp), intent(in) :: x     !! period T, s
        real(dp) :: y
        real(dp) :: sd(1, 1), sv(1, 1), sa(1, 1), psv(1, 1), ps(1, 1), tv(1), total
        real(dp) :: each(size(self%first))
        integer :: k, st(size(self%first))
        character(len=512) :: msg(size(self%first))
        y = ieee_value(1.0_dp, ieee_quiet_nan)
        msg = ''
        ! the records side by side (OpenMP), summed in order afterwards (the same bits
        ! whatever the threads)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(k, sd, sv, sa, psv, ps)
        do k = 1, size(self%first)
            associate (a => self%accel(self%first(k):self%first(k) + self%npts(k) - 1))
                call sdof_spectrum(a, self%dt(k), [x], [suite_damping], STANDARD_GRAVITY, sd, &
                                   sv, sa, st(k), msg(k), peaks=SDOF_PEAKS_EXACT, threads=1)
            end associate
            call pseudo_spectra([x], sd, STANDARD_GRAVITY, 0.0_dp, psv, ps)
            each(k) = ps(1, 1)
        end do
        !$omp end parallel do
        total = 0.0_dp
        do k = 1, size(self%first)
            if (st(k) /= SEISPULSE_SUCCESS) then
                if (self%stat == SEISPULSE_SUCCESS) then
                    self%stat = st(k)
                    self%msg = 'record '//int_str(k)//': '//trim(msg(k))
                end if
                return
            end if
            total = total + self%weight(k)*each(k)
        end do
        call suite_target_values(self%target, [x], tv, st(1), msg(1))
        if (st(1) /= SEISPULSE_SUCCESS) then
            if (self%stat == SEISPULSE_SUCCESS) then
                self%stat = st(1)
                self%msg = trim(msg(1))
            end if
            return
        end if
        y = (total/real(size(self%first), dp))/tv(1)
    end function suite_ratio_eval

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

    !> min_records >= 1 and n_rec >= min_records (rule (a) or the caller's own least count);
    !> head names the count in the message.
    pure subroutine check_count(n_rec, min_records, head, stat, errmsg)
        integer, intent(in) :: n_rec, min_records
        character(len=*), intent(in) :: head
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (min_records < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'min_records = '// &
                           int_str(min_records)//': must be >= 1')
        else if (n_rec < min_records) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, head//' the suite needs '// &
                           'at least '//int_str(min_records)//' (EN 1998-1 3.2.3.1.2(4)a: '// &
                           'at least 3)')
        end if
    end subroutine check_count

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
        call check_count(n_rec, min_records, 'n = '//int_str(n_rec)//' records:', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
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
