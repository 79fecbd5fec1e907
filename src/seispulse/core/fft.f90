!> A small radix-2 fast Fourier transform (iterative Cooley-Tukey [CT65], decimation in time).
!>
!> Convention (that of numpy.fft.fft): for x of length n = 2^m,
!>     X_k = sum_{j=0}^{n-1} x_j exp(-2 pi i j k / n),   k = 0 .. n-1,
!> and the inverse X -> x carries the factor 1/n. The twiddle factors are evaluated
!> directly, exp(-2 pi i k / n) = cos(pi 2k/n) - i sin(pi 2k/n) with exact argument
!> reduction (seispulse_special sin_pi, cos_pi), never by a recurrence, so the error
!> grows like eps log2(n) (doc/intensity.md section 5).
module seispulse_fft
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_format, only: int_str
    use seispulse_special, only: sin_pi, cos_pi
    implicit none
    private

    public :: fft, next_power_of_two, is_power_of_two

contains

    !> True when n is a power of two (1, 2, 4, ...).
    elemental logical function is_power_of_two(n)
        integer, intent(in) :: n  !! the length
        is_power_of_two = .false.
        if (n >= 1) is_power_of_two = iand(n, n - 1) == 0
    end function is_power_of_two

    !> The smallest power of two >= n (1 for n <= 1); -1 when it does not fit in an
    !> integer (n > 2^30).
    elemental integer function next_power_of_two(n)
        integer, intent(in) :: n  !! the length
        next_power_of_two = 1
        do while (next_power_of_two < n)
            if (next_power_of_two >= 2**30) then
                next_power_of_two = -1
                return
            end if
            next_power_of_two = 2 * next_power_of_two
        end do
    end function next_power_of_two

    !> In-place discrete Fourier transform of x (size a power of two), numpy's sign
    !> convention; `inverse` = .true. gives the inverse transform (with the 1/n).
    subroutine fft(x, stat, errmsg, inverse)
        complex(dp), intent(inout) :: x(:)                    !! the sequence, size 2^m
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        logical, intent(in), optional :: inverse              !! inverse transform (default no)
        integer :: n, i, j, k, len, half, step
        real(dp) :: sgn
        complex(dp) :: w, t
        complex(dp), allocatable :: tw(:)
        stat = SEISPULSE_SUCCESS
        n = size(x)
        if (.not. is_power_of_two(n)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'x: size '//int_str(n) &
                           //', must be a power of two >= 1')
            return
        end if
        if (n == 1) return
        sgn = -1.0_dp
        if (present(inverse)) then
            if (inverse) sgn = 1.0_dp
        end if
        ! twiddles w_k = exp(sgn 2 pi i k / n), k = 0 .. n/2 - 1
        allocate(tw(0:n / 2 - 1))
        do k = 0, n / 2 - 1
            tw(k) = cmplx(cos_pi(2.0_dp * real(k, dp) / real(n, dp)), &
                          sgn * sin_pi(2.0_dp * real(k, dp) / real(n, dp)), kind=dp)
        end do
        ! bit-reversal permutation
        j = 0
        do i = 0, n - 2
            if (i < j) then
                t = x(i + 1)
                x(i + 1) = x(j + 1)
                x(j + 1) = t
            end if
            k = n / 2
            do while (k >= 1 .and. iand(j, k) /= 0)
                j = ieor(j, k)
                k = k / 2
            end do
            j = ior(j, k)
        end do
        ! butterflies
        len = 2
        do while (len <= n)
            half = len / 2
            step = n / len
            do i = 0, n - 1, len
                do k = 0, half - 1
                    w = tw(k * step)
                    t = w * x(i + k + half + 1)
                    x(i + k + half + 1) = x(i + k + 1) - t
                    x(i + k + 1) = x(i + k + 1) + t
                end do
            end do
            len = 2 * len
        end do
        if (sgn > 0.0_dp) x = x / real(n, dp)
    end subroutine fft

end module seispulse_fft
