!> The number reader: token forms, exact conversion (compared bit for bit with the
!> compiler's own conversion of the same literal, done at compile time), refused
!> tokens, values out of range, and the message of value_at.
module test_number_reader
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_number_reader, only: parse_real, value_at, at_line, NUM_OK, NUM_INVALID, &
                                       NUM_RANGE
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_number_reader

contains

    subroutine collect_number_reader(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('parse_real: forms and correctly rounded values', test_values), &
                 new_unittest('parse_real: refused tokens and the range', test_refused), &
                 new_unittest('value_at and at_line: the messages', test_messages)]
    end subroutine collect_number_reader

    !> parse_real(tok) must be NUM_OK and bitwise equal to `expected`.
    subroutine check_exact(error, tok, expected)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: tok
        real(dp), intent(in) :: expected
        real(dp) :: x
        integer :: code
        call parse_real(tok, x, code)
        call check(error, code, NUM_OK, 'code of '//tok)
        if (allocated(error)) return
        call check(error, same_bits(x, expected), 'bits of '//tok)
    end subroutine check_exact

    subroutine test_values(error)
        type(test_error), allocatable, intent(out) :: error
        ! fast path (<= 15 digits, exponent within 22) and the slow path (17 digits,
        ! large exponents, subnormals): literals converted by the compiler
        call check_exact(error, '0.1', 0.1_dp)
        if (allocated(error)) return
        call check_exact(error, '-1.25E-03', -1.25e-3_dp)
        if (allocated(error)) return
        call check_exact(error, '+.5', 0.5_dp)
        if (allocated(error)) return
        call check_exact(error, '5.', 5.0_dp)
        if (allocated(error)) return
        call check_exact(error, '1d2', 100.0_dp)
        if (allocated(error)) return
        call check_exact(error, '123456789012345e-22', 123456789012345e-22_dp)
        if (allocated(error)) return
        call check_exact(error, '0.30000000000000004', 0.30000000000000004_dp)
        if (allocated(error)) return
        call check_exact(error, '9007199254740993', 9007199254740993.0_dp)
        if (allocated(error)) return
        call check_exact(error, '9.9999999999999994e307', 9.9999999999999994e307_dp)
        if (allocated(error)) return
        call check_exact(error, '4.9406564584124654e-324', tiny(1.0_dp) * epsilon(1.0_dp))
        if (allocated(error)) return
        call check_exact(error, '1e-500', 0.0_dp)
        if (allocated(error)) return
        call check_exact(error, '-0.000', -0.0_dp)
    end subroutine test_values

    subroutine test_refused(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=8), parameter :: BAD(9) = [character(len=8) :: 'nan', 'inf', '1.0.0', &
                                                 '1/2', '.', '-', '1e', '1e+', 'e5']
        real(dp) :: x
        integer :: code, i
        do i = 1, size(BAD)
            call parse_real(trim(BAD(i)), x, code)
            call check(error, code, NUM_INVALID, 'code of '//trim(BAD(i)))
            if (allocated(error)) return
            call check(error, x, 0.0_dp, rtol=0.0_dp, message='value of '//trim(BAD(i)))
            if (allocated(error)) return
        end do
        call parse_real('', x, code)
        call check(error, code, NUM_INVALID, 'empty token')
        if (allocated(error)) return
        call parse_real('1e308', x, code)
        call check(error, code, NUM_RANGE, '1e308')
        if (allocated(error)) return
        call parse_real('-2.5e99999999', x, code)
        call check(error, code, NUM_RANGE, 'huge exponent')
    end subroutine test_refused

    subroutine test_messages(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=200) :: msg
        real(dp) :: x
        integer :: stat
        call check(error, at_line('a/b.txt', 12) == 'a/b.txt:12: ', 'at_line')
        if (allocated(error)) return
        msg = ''
        call value_at('f.csv', 3, '2.5', x, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'value_at 2.5')
        if (allocated(error)) return
        call check(error, x, 2.5_dp, rtol=0.0_dp, message='value_at 2.5')
        if (allocated(error)) return
        call check(error, msg == '', 'value_at 2.5: no message')
        if (allocated(error)) return
        call value_at('f.csv', 3, '1,5', x, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'value_at 1,5')
        if (allocated(error)) return
        call check(error, msg == "f.csv:3: non-numeric value '1,5' (expected a number " &
                   //"such as -1.25E-03)", trim(msg))
        if (allocated(error)) return
        call value_at('f.csv', 7, '1e400', x, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'value_at 1e400')
        if (allocated(error)) return
        call check(error, msg == "f.csv:7: value '1e400' is out of the range of double " &
                   //"precision (|x| < 1e308 expected)", trim(msg))
    end subroutine test_messages

end module test_number_reader
