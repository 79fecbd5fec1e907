!> The library's texts are reentrant: int_str, real_str, num_str, quote and a validation
!> message with numbers in it (record_in_si: a sample whose product with g overflows),
!> called from several OpenMP threads at the same call sites, give exactly the texts of a
!> serial run. A function with a deferred-length character result would fail this:
!> gfortran keeps the length of such a result in a static variable of the caller, which
!> the threads share (wrong lengths, cut or garbled texts).
module test_reentrant
    use seispulse_kinds, only: dp
    use seispulse_format, only: int_str, real_str, num_str, quote
    use seispulse_pieces, only: record_in_si
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_reentrant

    !> distinct inputs (texts of many lengths) and passes over them in the threads
    integer, parameter :: NV = 997, PASSES = 60
    !> longest text kept (every text here is shorter)
    integer, parameter :: TLEN = 200

contains

    subroutine collect_reentrant(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('format functions and a message from OpenMP threads = serial', &
                              test_threads)]
    end subroutine collect_reentrant

    !> Input k (1..NV): an integer, a real and a name, of lengths varying with k.
    subroutine inputs(k, n, x, name)
        integer, intent(in) :: k
        integer, intent(out) :: n
        real(dp), intent(out) :: x
        character(len=:), allocatable, intent(out) :: name
        n = (k * 7919) / (1 + mod(k, 13)**3)
        if (mod(k, 2) == 0) n = -n
        x = real(k, dp) / 7.0_dp * 10.0_dp**(mod(k, 31) - 15)
        if (mod(k, 3) == 0) x = -x
        name = repeat('ab', mod(k, 29))
    end subroutine inputs

    !> The five texts of input k, each left in t(j)(1:nt(j)).
    subroutine texts(k, t, nt)
        integer, intent(in) :: k
        character(len=TLEN), intent(out) :: t(5)
        integer, intent(out) :: nt(5)
        integer :: n, stat
        real(dp) :: x, accel(3)
        real(dp), allocatable :: accel_si(:)
        character(len=:), allocatable :: name
        character(len=TLEN) :: msg
        call inputs(k, n, x, name)
        t(1) = int_str(n)
        nt(1) = len(int_str(n))
        t(2) = real_str(x)
        nt(2) = len(real_str(x))
        t(3) = num_str(x)
        nt(3) = len(num_str(x))
        t(4) = quote(name)
        nt(4) = len(quote(name))
        ! sample 1 + mod(k, 3) overflows g * accel: the message names it, its value and g
        accel = 1.0_dp
        accel(1 + mod(k, 3)) = huge(1.0_dp) / 2.0_dp * (1.0_dp + real(k, dp) * 1.0e-4_dp)
        msg = ''
        call record_in_si(accel, 2.0_dp + abs(x), accel_si, stat, msg, name=name)
        t(5) = msg
        nt(5) = len_trim(msg)
        if (stat == 0) nt(5) = -1
    end subroutine texts

    subroutine test_threads(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=TLEN) :: ref(5, NV), t(5)
        integer :: nref(5, NV), nt(5), k, i, j, bad, first
        do k = 1, NV
            call texts(k, ref(:, k), nref(:, k))
        end do
        ! the serial texts: what each is (a check that they are not all empty)
        call check(error, ref(1, 2)(1:nref(1, 2)) == '-1759' &
                   .and. ref(4, 1)(1:nref(4, 1)) == "'ab'" .and. nref(5, 1) > 0, &
                   'serial texts: '//ref(1, 2)(1:nref(1, 2))//' '//ref(4, 1)(1:nref(4, 1)))
        if (allocated(error)) return
        bad = 0
        first = 0
        !$omp parallel do num_threads(4) schedule(static, 1) private(k, j, t, nt) &
        !$omp reduction(+:bad) reduction(max:first)
        do i = 1, NV * PASSES
            k = 1 + mod(i * 389, NV)
            call texts(k, t, nt)
            do j = 1, 5
                if (nt(j) /= nref(j, k) .or. t(j) /= ref(j, k)) then
                    bad = bad + 1
                    first = max(first, k)
                end if
            end do
        end do
        !$omp end parallel do
        call check(error, bad == 0, int_str(bad)//' of '//int_str(5 * NV * PASSES) &
                   //' texts differ from the serial ones (e.g. input '//int_str(first)//')')
    end subroutine test_threads

end module test_reentrant
