!> The number texts of the tables: g_str against C's printf("%.<digits>g") and
!> shortest_str against Python's repr(float) (both computed independently, by Python,
!> for awkward doubles: subnormals, the largest double, -0, exact ties, powers of two),
!> the round trip and minimality of shortest_str for random doubles, and format_reals
!> against the single-number functions.
module test_format
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, &
                                             ieee_positive_inf, ieee_negative_inf
    use seispulse_kinds, only: dp
    use seispulse_format, only: g_str, shortest_str, format_reals, NUM_LEN
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_format

    !> Awkward doubles (values() below: 2^-1074, huge, 2^-1022, 2^60, ...) ...
    integer, parameter :: NX = 18
    !> ... Python's repr of each ...
    character(len=24), parameter :: repr(NX) = [character(len=24) :: '0.1', &
        '0.3333333333333333', '5e-324', '1.7976931348623157e+308', '-0.0', '1e-05', &
        '123456.5', '0.05', '100.0', '1e+16', '1000000000000000.0', &
        '2.2250738585072014e-308', '1.152921504606847e+18', '9007199254740992.0', &
        '-2.5e-07', '1e+23', '6.02214076e+23', '0.125']
    !> ... and "%.1g", "%.3g", "%.6g", "%.17g" % x
    character(len=24), parameter :: g1(NX) = [character(len=24) :: '0.1', '0.3', '5e-324', &
        '2e+308', '-0', '1e-05', '1e+05', '0.05', '1e+02', '1e+16', '1e+15', '2e-308', &
        '1e+18', '9e+15', '-2e-07', '1e+23', '6e+23', '0.1']
    character(len=24), parameter :: g3(NX) = [character(len=24) :: '0.1', '0.333', &
        '4.94e-324', '1.8e+308', '-0', '1e-05', '1.23e+05', '0.05', '100', '1e+16', &
        '1e+15', '2.23e-308', '1.15e+18', '9.01e+15', '-2.5e-07', '1e+23', '6.02e+23', &
        '0.125']
    character(len=24), parameter :: g6(NX) = [character(len=24) :: '0.1', '0.333333', &
        '4.94066e-324', '1.79769e+308', '-0', '1e-05', '123456', '0.05', '100', '1e+16', &
        '1e+15', '2.22507e-308', '1.15292e+18', '9.0072e+15', '-2.5e-07', '1e+23', &
        '6.02214e+23', '0.125']
    character(len=24), parameter :: g17(NX) = [character(len=24) :: '0.10000000000000001', &
        '0.33333333333333331', '4.9406564584124654e-324', '1.7976931348623157e+308', '-0', &
        '1.0000000000000001e-05', '123456.5', '0.050000000000000003', '100', &
        '10000000000000000', '1000000000000000', '2.2250738585072014e-308', &
        '1.152921504606847e+18', '9007199254740992', '-2.4999999999999999e-07', &
        '9.9999999999999992e+22', '6.0221407599999999e+23', '0.125']

contains

    subroutine collect_format(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('g_str: C''s %.<digits>g of awkward doubles', test_g), &
                 new_unittest('shortest_str: Python''s repr of awkward doubles', &
                              test_shortest), &
                 new_unittest('shortest_str: round trip and minimal, random doubles', &
                              test_random), &
                 new_unittest('format_reals: the texts of g_str and shortest_str', &
                              test_batch)]
    end subroutine collect_format

    !> The awkward doubles.
    function values() result(x)
        real(dp) :: x(NX)
        x = [0.1_dp, 1.0_dp / 3.0_dp, 0.0_dp, huge(1.0_dp), -0.0_dp, 1.0e-5_dp, &
             123456.5_dp, 0.05_dp, 100.0_dp, 1.0e16_dp, 1.0e15_dp, 2.0_dp**(-1022), &
             2.0_dp**60, 9007199254740993.0_dp, -2.5e-7_dp, 1.0e23_dp, 6.02214076e23_dp, &
             0.125_dp]
        x(3) = transfer(1_int64, 1.0_dp)      ! the least subnormal, 2^-1074 = 5e-324
    end function values

    subroutine test_g(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x(NX), nan
        integer :: i
        x = values()
        do i = 1, NX
            call check(error, g_str(x(i), 1) == trim(g1(i)), '%.1g of '//trim(repr(i)) &
                       //': '//g_str(x(i), 1))
            if (allocated(error)) return
            call check(error, g_str(x(i), 3) == trim(g3(i)), '%.3g of '//trim(repr(i)) &
                       //': '//g_str(x(i), 3))
            if (allocated(error)) return
            call check(error, g_str(x(i), 6) == trim(g6(i)), '%.6g of '//trim(repr(i)) &
                       //': '//g_str(x(i), 6))
            if (allocated(error)) return
            call check(error, g_str(x(i), 17) == trim(g17(i)), '%.17g of '//trim(repr(i)) &
                       //': '//g_str(x(i), 17))
            if (allocated(error)) return
        end do
        ! exact ties round to even (C and Python): 0.125 -> 0.12, 0.375 -> 0.38, 2.5 -> 2
        call check(error, g_str(0.125_dp, 2) == '0.12', '0.125 to 2 digits')
        if (allocated(error)) return
        call check(error, g_str(0.375_dp, 2) == '0.38', '0.375 to 2 digits')
        if (allocated(error)) return
        call check(error, g_str(2.5_dp, 1) == '2' .and. g_str(-3.5_dp, 1) == '-4', &
                   '2.5, -3.5 to 1 digit')
        if (allocated(error)) return
        ! a carry into a new digit: 9.9999996 to 6 digits is 10; 99999.95 to 6 is 99999.9
        ! (99999.95 is 99999.949999... as a double)
        call check(error, g_str(9.9999996_dp, 6) == '10', '9.9999996 to 6 digits')
        if (allocated(error)) return
        call check(error, g_str(99999.95_dp, 6) == '99999.9', '99999.95 to 6 digits')
        if (allocated(error)) return
        call check(error, g_str(999999.5_dp, 6) == '1e+06', '999999.5 to 6 digits')
        if (allocated(error)) return
        nan = ieee_value(1.0_dp, ieee_quiet_nan)
        call check(error, g_str(nan, 6) == 'nan' .and. &
                   g_str(ieee_value(1.0_dp, ieee_positive_inf), 6) == 'inf' .and. &
                   g_str(ieee_value(1.0_dp, ieee_negative_inf), 6) == '-inf', 'nan, inf')
    end subroutine test_g

    subroutine test_shortest(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x(NX), y
        integer :: i, ios
        character(len=24) :: text
        x = values()
        do i = 1, NX
            call check(error, shortest_str(x(i)) == trim(repr(i)), 'repr of '//trim(repr(i)) &
                       //': '//shortest_str(x(i)))
            if (allocated(error)) return
            text = repr(i)
            read(text, *, iostat=ios) y
            call check(error, ios == 0 .and. same_bits(y, x(i)), 'literal of '//trim(repr(i)))
            if (allocated(error)) return
        end do
        call check(error, shortest_str(ieee_value(1.0_dp, ieee_quiet_nan)) == 'nan' .and. &
                   shortest_str(ieee_value(1.0_dp, ieee_negative_inf)) == '-inf', 'nan, -inf')
    end subroutine test_shortest

    !> Random doubles (random bit patterns, and random magnitudes 1e-300..1e300): the
    !> text reads back to the same bits, has at most 17 significant digits, and one
    !> digit fewer (correctly rounded) does not read back.
    subroutine test_random(error)
        type(test_error), allocatable, intent(out) :: error
        integer, allocatable :: seed(:)
        real(dp) :: u(3), x, y
        integer(int64) :: bits
        integer :: i, n, ios, nd
        character(len=NUM_LEN) :: s, shorter
        call random_seed(size=n)
        allocate(seed(n))
        seed = [(12345 + 7 * i, i = 1, n)]
        call random_seed(put=seed)
        do i = 1, 20000
            call random_number(u)
            if (mod(i, 2) == 0) then
                bits = ior(ishft(int(u(1) * 2.0_dp**31, int64), 33), &
                           int(u(2) * 2.0_dp**33, int64))
                if (u(3) < 0.5_dp) bits = ior(bits, ishft(1_int64, 32))
                if (ibits(bits, 52, 11) == 2047) cycle      ! inf or NaN (maybe signalling)
                x = transfer(bits, 1.0_dp)
            else
                x = (2.0_dp * u(1) - 1.0_dp) * 10.0_dp**(600.0_dp * u(2) - 300.0_dp)
            end if
            s = shortest_str(x)
            read(s, *, iostat=ios) y
            call check(error, ios == 0 .and. same_bits(x, y), 'round trip of '//trim(s))
            if (allocated(error)) return
            nd = digit_count(trim(s))
            call check(error, nd <= 17, 'at most 17 digits: '//trim(s))
            if (allocated(error)) return
            ! (one digit fewer of a number near the largest double may overflow)
            if (nd > 1 .and. abs(x) < 1.0e308_dp) then
                shorter = g_str(x, nd - 1)
                read(shorter, *, iostat=ios) y
                call check(error, ios /= 0 .or. .not. same_bits(x, y), 'minimal: '//trim(s) &
                           //' vs '//trim(shorter))
                if (allocated(error)) return
            end if
        end do
    end subroutine test_random

    !> Significant digits of a decimal text (leading zeros and the exponent aside).
    pure integer function digit_count(s)
        character(len=*), intent(in) :: s
        integer :: i, first, last, e
        e = scan(s, 'eE')
        if (e == 0) e = len(s) + 1
        first = 0
        last = 0
        do i = 1, e - 1
            if (s(i:i) >= '1' .and. s(i:i) <= '9') then
                if (first == 0) first = i
                last = i
            end if
        end do
        digit_count = 0
        if (first == 0) return
        do i = first, last
            if (s(i:i) /= '.') digit_count = digit_count + 1
        end do
    end function digit_count

    subroutine test_batch(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x(150)
        character(len=NUM_LEN) :: a(150), b(150)
        integer :: i
        ! more than one chunk of the batched conversion
        x = [(real(i, dp) / 7.0_dp * 10.0_dp**(mod(i, 40) - 20), i = 1, 150)]
        x(17) = -0.0_dp
        x(99) = ieee_value(1.0_dp, ieee_quiet_nan)
        call format_reals(x, 4, a, 0, b)
        do i = 1, size(x)
            call check(error, trim(a(i)) == g_str(x(i), 4) .and. &
                       trim(b(i)) == shortest_str(x(i)), 'number '//shortest_str(x(i)))
            if (allocated(error)) return
        end do
    end subroutine test_batch

end module test_format
