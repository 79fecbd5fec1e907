!> A small unit-test harness in the shape of fortran-lang/test-drive (clean room).
!>
!> A test is a subroutine `run(error)`; a failed check allocates `error` with a
!> message and the test returns at once (`if (allocated(error)) return`).
module testing
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use, intrinsic :: iso_fortran_env, only: int64
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: test_error, unit_test, new_unittest, check, run_suite, same_bits

    type :: test_error
        character(len=:), allocatable :: message
    end type test_error

    abstract interface
        subroutine test_iface(error)
            import :: test_error
            type(test_error), allocatable, intent(out) :: error
        end subroutine test_iface
    end interface

    type :: unit_test
        character(len=:), allocatable :: name
        procedure(test_iface), pointer, nopass :: run => null()
    end type unit_test

    interface check
        module procedure check_condition
        module procedure check_real
        module procedure check_real_array
        module procedure check_int
    end interface check

contains

    function new_unittest(name, run) result(t)
        character(len=*), intent(in) :: name
        procedure(test_iface) :: run
        type(unit_test) :: t
        t%name = name
        t%run => run
    end function new_unittest

    !> Fail with `message` unless `condition` holds.
    subroutine check_condition(error, condition, message)
        type(test_error), allocatable, intent(inout) :: error
        logical, intent(in) :: condition
        character(len=*), intent(in), optional :: message
        if (condition) return
        allocate(error)
        if (present(message)) then
            error%message = message
        else
            error%message = 'condition not satisfied'
        end if
    end subroutine check_condition

    !> Fail unless |actual - expected| <= max(atol, rtol |expected|); equal infinities
    !> pass, NaN never passes (default rtol = 1e-14, atol = 0).
    subroutine check_real(error, actual, expected, rtol, atol, message)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: actual, expected
        real(dp), intent(in), optional :: rtol, atol
        character(len=*), intent(in), optional :: message
        real(dp) :: rt, at, tol
        character(len=200) :: buf
        rt = 1.0e-14_dp
        at = 0.0_dp
        if (present(rtol)) rt = rtol
        if (present(atol)) at = atol
        if (.not. (ieee_is_nan(actual) .or. ieee_is_nan(expected))) then
            if (abs(expected) > huge(expected) .or. abs(actual) > huge(actual)) then
                ! infinities: only the same infinity matches
                if (abs(expected) > huge(expected) .and. abs(actual) > huge(actual) &
                    .and. (expected > 0.0_dp .eqv. actual > 0.0_dp)) return
            else
                tol = max(at, rt * abs(expected))
                if (abs(actual - expected) <= tol) return
            end if
        end if
        allocate(error)
        write(buf, '(a, es24.16, a, es24.16, a, es10.3)') 'got ', actual, ' expected ', &
            expected, ' rel.diff ', abs(actual - expected) / max(abs(expected), tiny(1.0_dp))
        error%message = trim(buf)
        if (present(message)) error%message = message//': '//error%message
    end subroutine check_real

    !> Element-wise check_real; reports the first failing index.
    subroutine check_real_array(error, actual, expected, rtol, atol, message)
        type(test_error), allocatable, intent(inout) :: error
        real(dp), intent(in) :: actual(:), expected(:)
        real(dp), intent(in), optional :: rtol, atol
        character(len=*), intent(in), optional :: message
        integer :: i
        character(len=40) :: idx
        if (size(actual) /= size(expected)) then
            allocate(error)
            error%message = 'array sizes differ'
            return
        end if
        do i = 1, size(actual)
            call check_real(error, actual(i), expected(i), rtol, atol)
            if (allocated(error)) then
                write(idx, '(a, i0, a)') 'index ', i, ': '
                error%message = trim(idx)//error%message
                if (present(message)) error%message = message//': '//error%message
                return
            end if
        end do
    end subroutine check_real_array

    subroutine check_int(error, actual, expected, message)
        type(test_error), allocatable, intent(inout) :: error
        integer, intent(in) :: actual, expected
        character(len=*), intent(in), optional :: message
        character(len=80) :: buf
        if (actual == expected) return
        allocate(error)
        write(buf, '(a, i0, a, i0)') 'got ', actual, ' expected ', expected
        error%message = trim(buf)
        if (present(message)) error%message = message//': '//error%message
    end subroutine check_int

    !> Run every test of a suite, one line each; count passes and failures.
    subroutine run_suite(suite_name, tests, unit, npass, nfail)
        character(len=*), intent(in) :: suite_name
        type(unit_test), intent(in) :: tests(:)
        integer, intent(in) :: unit
        integer, intent(inout) :: npass, nfail
        type(test_error), allocatable :: error
        integer :: i
        do i = 1, size(tests)
            call tests(i)%run(error)
            if (allocated(error)) then
                nfail = nfail + 1
                write(unit, '(a)') 'FAIL '//suite_name//'/'//tests(i)%name//': '//error%message
                deallocate(error)
            else
                npass = npass + 1
                write(unit, '(a)') 'ok   '//suite_name//'/'//tests(i)%name
            end if
        end do
    end subroutine run_suite

    !> a and b have the same bits (a NaN equals only the same NaN, -0 differs from +0).
    pure logical function same_bits(a, b)
        real(dp), intent(in) :: a, b  !! the two values
        same_bits = transfer(a, 1_int64) == transfer(b, 1_int64)
    end function same_bits

end module testing
