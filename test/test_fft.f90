!> Radix-2 FFT: against a direct DFT, the inverse, the power-of-two helpers.
module test_fft
    use, intrinsic :: iso_fortran_env, only: int64
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT
    use seispulse_fft, only: fft, next_power_of_two, is_power_of_two
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_fft

contains

    subroutine collect_fft(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('FFT equals the direct DFT (n = 1 .. 1024)', test_direct), &
                 new_unittest('inverse FFT restores the sequence', test_inverse), &
                 new_unittest('a cosine on a bin: one line of height n/2', test_cosine), &
                 new_unittest('size not a power of two is an error', test_bad_size), &
                 new_unittest('power-of-two helpers', test_helpers)]
    end subroutine collect_fft

    !> Deterministic test data (a linear congruential sequence in [-1, 1)).
    subroutine sample_data(x)
        complex(dp), intent(out) :: x(:)
        integer :: i
        integer, parameter :: m = 2147483647
        integer :: s
        real(dp) :: re, im
        s = 12345
        do i = 1, size(x)
            s = int(mod(16807_int64 * int(s, int64), int(m, int64)))
            re = 2.0_dp * real(s, dp) / real(m, dp) - 1.0_dp
            s = int(mod(16807_int64 * int(s, int64), int(m, int64)))
            im = 2.0_dp * real(s, dp) / real(m, dp) - 1.0_dp
            x(i) = cmplx(re, im, kind=dp)
        end do
    end subroutine sample_data

    subroutine test_direct(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: sizes(6), is, n, j, k, stat
        complex(dp), allocatable :: x(:), y(:), z(:)
        real(dp) :: arg, scale
        real(dp), parameter :: two_pi = 6.283185307179586476925286766559_dp
        sizes = [1, 2, 4, 8, 64, 1024]
        do is = 1, size(sizes)
            n = sizes(is)
            allocate(x(n), y(n), z(n))
            call sample_data(x)
            ! direct DFT, X_k = sum x_j exp(-2 pi i j k / n), in extended accumulation
            do k = 0, n - 1
                z(k + 1) = (0.0_dp, 0.0_dp)
                do j = 0, n - 1
                    arg = -two_pi * real(mod(j * k, n), dp) / real(n, dp)
                    z(k + 1) = z(k + 1) + x(j + 1) * cmplx(cos(arg), sin(arg), kind=dp)
                end do
            end do
            y = x
            call fft(y, stat)
            call check(error, stat, SEISPULSE_SUCCESS)
            if (allocated(error)) return
            scale = sqrt(real(n, dp))
            call check(error, real(y, dp), real(z, dp), rtol=0.0_dp, atol=1.0e-13_dp * scale, &
                       message='real part')
            if (allocated(error)) return
            call check(error, aimag(y), aimag(z), rtol=0.0_dp, atol=1.0e-13_dp * scale, &
                       message='imaginary part')
            if (allocated(error)) return
            deallocate(x, y, z)
        end do
    end subroutine test_direct

    subroutine test_inverse(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: x(256), y(256)
        integer :: stat
        call sample_data(x)
        y = x
        call fft(y, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call fft(y, stat, inverse=.true.)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        call check(error, real(y, dp), real(x, dp), rtol=0.0_dp, atol=1.0e-15_dp)
        if (allocated(error)) return
        call check(error, aimag(y), aimag(x), rtol=0.0_dp, atol=1.0e-15_dp)
    end subroutine test_inverse

    !> cos(2 pi 5 j / 64): X_5 = X_59 = 32, every other bin 0.
    subroutine test_cosine(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: x(64)
        real(dp) :: expect(64)
        integer :: j, stat
        real(dp), parameter :: two_pi = 6.283185307179586476925286766559_dp
        do j = 0, 63
            x(j + 1) = cmplx(cos(two_pi * 5.0_dp * real(j, dp) / 64.0_dp), 0.0_dp, kind=dp)
        end do
        call fft(x, stat)
        call check(error, stat, SEISPULSE_SUCCESS)
        if (allocated(error)) return
        expect = 0.0_dp
        expect(6) = 32.0_dp
        expect(60) = 32.0_dp
        call check(error, abs(x), expect, rtol=0.0_dp, atol=1.0e-13_dp)
    end subroutine test_cosine

    subroutine test_bad_size(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: x(12), e(0)
        integer :: stat
        character(len=200) :: msg
        x = (1.0_dp, 0.0_dp)
        msg = ''
        call fft(x, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT)
        if (allocated(error)) return
        call check(error, index(msg, 'x: size 12') == 1, trim(msg))
        if (allocated(error)) return
        call fft(e, stat)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'size 0')
    end subroutine test_bad_size

    subroutine test_helpers(error)
        type(test_error), allocatable, intent(out) :: error
        call check(error, next_power_of_two(0), 1)
        if (allocated(error)) return
        call check(error, next_power_of_two(1), 1)
        if (allocated(error)) return
        call check(error, next_power_of_two(5), 8)
        if (allocated(error)) return
        call check(error, next_power_of_two(4096), 4096)
        if (allocated(error)) return
        call check(error, next_power_of_two(4097), 8192)
        if (allocated(error)) return
        call check(error, next_power_of_two(2**30 + 1), -1)
        if (allocated(error)) return
        call check(error, all(is_power_of_two([1, 2, 1024, 2**30])), 'powers')
        if (allocated(error)) return
        call check(error, .not. any(is_power_of_two([0, -4, 3, 12, 2**30 - 1])), 'non-powers')
    end subroutine test_helpers

end module test_fft
