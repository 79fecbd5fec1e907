!> Characteristic lengths for normalizing sliding displacements by dimensional analysis
!> (section 1 of Ref. [GR]; doc/sliding.md section 6): D_c = A_g^a V_g^b D_g^c t^d with
!> a + b + c = 1 (length, Eq. 1.26a) and 2a + b - d = 0 (time, Eq. 1.26b).
module seispulse_sliding_norm
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str
    use seispulse_optval, only: optval
    use seispulse_pulses, only: exp_consts_t, exp_consts
    implicit none
    private

    public :: characteristic_length, basic_lengths, table_1_2_exponents, table_1_3
    public :: NBASIC

    integer, parameter :: NBASIC = 6  !! number of the basic lengths of Eq. 1.28

contains

    !> D_c = A_g^a V_g^b D_g^c t^d (Eq. 1.25), checking the dimension constraints 1.26.
    subroutine characteristic_length(a, b, c, d, ag, vg, dg, td, dc, stat, errmsg)
        real(dp), intent(in) :: a, b, c, d                    !! exponents of A_g, V_g, D_g, t
        real(dp), intent(in) :: ag                            !! A_g (m/s^2) > 0
        real(dp), intent(in) :: vg                            !! V_g (m/s) > 0
        real(dp), intent(in) :: dg                            !! D_g (m) > 0
        real(dp), intent(in) :: td                            !! t (s) > 0
        real(dp), intent(out) :: dc                           !! D_c (m)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp), parameter :: tol = 1.0e-12_dp
        dc = 0.0_dp
        call check_scales(ag, vg, dg, td, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (ieee_is_finite(a) .and. ieee_is_finite(b) .and. ieee_is_finite(c) &
                   .and. ieee_is_finite(d))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'a, b, c, d: exponents must be finite numbers')
        else if (abs(a + b + c - 1.0_dp) > tol * max(1.0_dp, abs(a) + abs(b) + abs(c))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'a + b + c = ' &
                           //real_str(a + b + c)//': must be 1 (D_c is a length, Eq. 1.26a)')
        else if (abs(2.0_dp * a + b - d) > tol * max(1.0_dp, 2.0_dp * abs(a) + abs(b) + abs(d))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, '2a + b - d = ' &
                           //real_str(2.0_dp * a + b - d)//': must be 0 (no time left, Eq. 1.26b)')
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        ! in logs: powers of extreme scales can over- or underflow while D_c does not
        dc = exp(a * log(ag) + b * log(vg) + c * log(dg) + d * log(td))
    end subroutine characteristic_length

    !> The six basic lengths of Eq. 1.28 a-f: A_g t^2, V_g^2/A_g, D_g, V_g t,
    !> V_g D_g/(A_g t), A_g D_g t/V_g.
    subroutine basic_lengths(ag, vg, dg, td, lengths, stat, errmsg)
        real(dp), intent(in) :: ag                            !! A_g (m/s^2) > 0
        real(dp), intent(in) :: vg                            !! V_g (m/s) > 0
        real(dp), intent(in) :: dg                            !! D_g (m) > 0
        real(dp), intent(in) :: td                            !! t (s) > 0
        real(dp), intent(out) :: lengths(NBASIC)              !! D_c of 1.28a-f (m)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        lengths = 0.0_dp
        call check_scales(ag, vg, dg, td, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        lengths = [ag * td * td, vg * vg / ag, dg, vg * td, vg * dg / (ag * td), &
                   ag * dg * td / vg]
    end subroutine basic_lengths

    !> Exponents (a, b, c, d) of the cell (row, col) of Table 1.2 `table` ('a'..'f'):
    !> the two free exponents are (row, column) = (b, a), (c, a), (d, a), (c, b), (d, b),
    !> (d, c) for tables a..f (Eqs. 1.27a-f; the printed captions all say "a, c").
    subroutine table_1_2_exponents(table, row, col, a, b, c, d, stat, errmsg)
        character(len=*), intent(in) :: table                 !! 'a' .. 'f'
        real(dp), intent(in) :: row                           !! value of the row exponent
        real(dp), intent(in) :: col                           !! value of the column exponent
        real(dp), intent(out) :: a, b, c, d                   !! exponents of A_g, V_g, D_g, t
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        a = 0.0_dp
        b = 0.0_dp
        c = 0.0_dp
        d = 0.0_dp
        select case (trim(adjustl(table)))
        case ('a')   ! eliminate c, d (1.27a)
            b = row
            a = col
            c = 1.0_dp - a - b
            d = 2.0_dp * a + b
        case ('b')   ! eliminate b, d (1.27b)
            c = row
            a = col
            b = 1.0_dp - a - c
            d = 2.0_dp * a + b
        case ('c')   ! eliminate b, c (1.27c)
            d = row
            a = col
            b = d - 2.0_dp * a
            c = 1.0_dp - a - b
        case ('d')   ! eliminate a, d (1.27d)
            c = row
            b = col
            a = 1.0_dp - b - c
            d = 2.0_dp * a + b
        case ('e')   ! eliminate a, c (1.27e, with V_g^2 in its first group: doc/sliding.md Corrections 6)
            d = row
            b = col
            a = 0.5_dp * (d - b)
            c = 1.0_dp - a - b
        case ('f')   ! eliminate a, b (1.27f)
            d = row
            c = col
            a = d + c - 1.0_dp
            b = 1.0_dp - a - c
        case default
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'table = '''//trim(table) &
                           //''': unknown (allowed: a, b, c, d, e, f)')
        end select
    end subroutine table_1_2_exponents

    !> Table 1.3: the basic lengths of Eq. 1.28 over A_g t_d^2 for the exponential pulse,
    !> from their formulas with V_g = k A_g t_d and D_g = k A_g t_d^2/n (n = 2 half cycle,
    !> 1 full cycle; Eq. 1.29). Rows in the order of 1.28a-f.
    !> full is optional (default .false., as Python's `sliding.table_1_3`); when omitted,
    !> pass ratios and stat by keyword.
    subroutine table_1_3(beta, full, ratios, stat, errmsg)
        real(dp), intent(in) :: beta                          !! pulse shape, finite or -inf
        !> full cycle; default .false.
        logical, intent(in), optional :: full
        real(dp), intent(out) :: ratios(NBASIC)               !! D_c/(A_g t_d^2)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        type(exp_consts_t) :: cst
        real(dp) :: n
        logical :: full_in
        full_in = optval(full, .false.)
        ratios = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (.not. (beta < huge(beta))) then
            ! the spike has V_g = 0: the ratios with V_g in a denominator do not exist
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'beta = '//real_str(beta) &
                           //': must be finite or -inf (the spike has no velocity scale)')
            return
        end if
        cst = exp_consts(beta)
        n = 2.0_dp
        if (full_in) n = 1.0_dp
        call basic_lengths(1.0_dp, cst%vg, cst%vg / n, 1.0_dp, ratios, stat, errmsg)
    end subroutine table_1_3

    subroutine check_scales(ag, vg, dg, td, stat, errmsg)
        real(dp), intent(in) :: ag, vg, dg, td
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (.not. positive(ag)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ag = '//real_str(ag) &
                           //': must be a finite acceleration > 0')
        else if (.not. positive(vg)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vg = '//real_str(vg) &
                           //': must be a finite velocity > 0')
        else if (.not. positive(dg)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dg = '//real_str(dg) &
                           //': must be a finite displacement > 0')
        else if (.not. positive(td)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'td = '//real_str(td) &
                           //': must be a finite time > 0')
        end if
    contains
        logical function positive(x)
            real(dp), intent(in) :: x
            positive = .not. outside(x, 0.0_dp, huge(x), .true., .false.)
        end function positive
    end subroutine check_scales

end module seispulse_sliding_norm
