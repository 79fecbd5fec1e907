!> Argument checks shared by every model: NaN-safe range tests (an ordered
!> comparison on a NaN raises the invalid flag and traps in checked builds) and the
!> checks of output grids. Messages name the argument first, like every library message.
module seispulse_checks
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_format, only: real_str, int_str
    implicit none
    private

    public :: outside, finite_positive, finite_at_least, positive, in_open, in_closed, &
              check_finite_times, check_ascending_times, check_output_grid, check_history_sizes, &
              check_spectrum_periods

contains

    !> x is finite and > 0.
    elemental logical function finite_positive(x)
        real(dp), intent(in) :: x  !! the value
        finite_positive = .false.
        if (ieee_is_finite(x)) finite_positive = x > 0.0_dp
    end function finite_positive

    !> x is finite and >= lo.
    elemental logical function finite_at_least(x, lo)
        real(dp), intent(in) :: x   !! the value
        real(dp), intent(in) :: lo  !! the least allowed value
        finite_at_least = .false.
        if (ieee_is_finite(x)) finite_at_least = x >= lo
    end function finite_at_least

    !> x > 0 (+inf allowed) and not NaN.
    elemental logical function positive(x)
        real(dp), intent(in) :: x  !! the value
        positive = .false.
        if (.not. ieee_is_nan(x)) positive = x > 0.0_dp
    end function positive

    !> lo < x < hi, x not NaN.
    elemental logical function in_open(x, lo, hi)
        real(dp), intent(in) :: x       !! the value
        real(dp), intent(in) :: lo, hi  !! the open range
        in_open = .not. outside(x, lo, hi, .true., .true.)
    end function in_open

    !> lo <= x <= hi, x not NaN.
    elemental logical function in_closed(x, lo, hi)
        real(dp), intent(in) :: x       !! the value
        real(dp), intent(in) :: lo, hi  !! the closed range
        in_closed = .not. outside(x, lo, hi, .false., .false.)
    end function in_closed

    !> x is NaN or outside [lo, hi] (an end excluded when open): the range check of every
    !> input. NaN is tested first: an ordered comparison on NaN raises the invalid flag
    !> (and traps in checked builds).
    elemental logical function outside(x, lo, hi, open_lo, open_hi)
        real(dp), intent(in) :: x        !! the value
        real(dp), intent(in) :: lo, hi   !! the range
        logical, intent(in) :: open_lo   !! lo itself is outside
        logical, intent(in) :: open_hi   !! hi itself is outside
        if (ieee_is_nan(x)) then
            outside = .true.
        else if (open_lo) then
            outside = .not. (x > lo)
        else
            outside = x < lo
        end if
        if (outside) return
        if (open_hi) then
            outside = .not. (x < hi)
        else
            outside = x > hi
        end if
    end function outside

    !> Times that must all be finite: a message naming the first one that is not, name(i),
    !> with `unit` (e.g. ' (s)') at its end when given.
    subroutine check_finite_times(t, name, stat, errmsg, unit)
        real(dp), intent(in) :: t(:)                          !! the times
        character(len=*), intent(in) :: name                  !! their name in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> appended to the message (e.g. " (s)"); absent: nothing
        character(len=*), intent(in), optional :: unit
        integer :: i
        character(len=24) :: idx
        character(len=:), allocatable :: msg
        stat = SEISPULSE_SUCCESS
        do i = 1, size(t)
            if (.not. ieee_is_finite(t(i))) then
                write(idx, '(i0)') i
                msg = name//'('//trim(idx)//') = '//real_str(t(i))//': must be a finite number'
                if (present(unit)) msg = msg//unit
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, msg)
                return
            end if
        end do
    end subroutine check_finite_times

    !> Output times of an integrator: finite and ascending (a message naming t(i)).
    subroutine check_ascending_times(t, name, stat, errmsg)
        real(dp), intent(in) :: t(:)                          !! the times
        character(len=*), intent(in) :: name                  !! their name in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i
        character(len=24) :: idx
        call check_finite_times(t, name, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        do i = 2, size(t)
            if (t(i) < t(i - 1)) then
                write(idx, '(i0)') i
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, name//'('//trim(idx) &
                               //') = '//real_str(t(i))//': the times must be ascending')
                return
            end if
        end do
    end subroutine check_ascending_times

    !> Optional output histories of an integrator: the times t_grid and the two grids
    !> x_grid, y_grid all present or all absent, of one size, t_grid finite and ascending.
    subroutine check_output_grid(x_name, y_name, stat, errmsg, t_grid, x_grid, y_grid)
        character(len=*), intent(in) :: x_name, y_name        !! names of the grids in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> output times (s); all three grids present or all absent (no output)
        real(dp), intent(in), optional :: t_grid(:)
        !> first output grid; present with t_grid, else absent
        real(dp), intent(in), optional :: x_grid(:)
        !> second output grid; present with t_grid, else absent
        real(dp), intent(in), optional :: y_grid(:)
        character(len=:), allocatable :: together
        stat = SEISPULSE_SUCCESS
        if (.not. (present(t_grid) .or. present(x_grid) .or. present(y_grid))) return
        together = ': missing (t_grid, '//x_name//' and '//y_name//' go together)'
        if (.not. present(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't_grid: missing (' &
                           //x_name//' and '//y_name//' need the output times)')
        else if (.not. present(x_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, x_name//together)
        else if (.not. present(y_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, y_name//together)
        else if (size(x_grid) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, x_name &
                           //': must have the size of t_grid')
        else if (size(y_grid) /= size(t_grid)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, y_name &
                           //': must have the size of t_grid')
        else
            call check_ascending_times(t_grid, 't_grid', stat, errmsg)
        end if
    end subroutine check_output_grid

    !> Periods of a response spectrum and its output: `nout` (the size of the output array
    !> named `outname`) equal to size(periods), every period finite and >= 0 (s). The
    !> messages name the output or periods(i).
    pure subroutine check_spectrum_periods(periods, nout, outname, stat, errmsg)
        real(dp), intent(in) :: periods(:)                    !! periods T, s
        integer, intent(in) :: nout                           !! size of the output array
        character(len=*), intent(in) :: outname               !! its name in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i
        stat = SEISPULSE_SUCCESS
        if (nout /= size(periods)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, outname// &
                           ': must have the size of periods ('//int_str(size(periods))//')')
            return
        end if
        do i = 1, size(periods)
            if (outside(periods(i), 0.0_dp, huge(1.0_dp), .false., .false.)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'periods('//int_str(i)// &
                               ') = '//real_str(periods(i))//': the period (s) must be '// &
                               'finite and >= 0')
                return
            end if
        end do
    end subroutine check_spectrum_periods

    !> Optional histories at the samples of a record of n samples: each one present has n
    !> elements, else a message naming it ('<name>: must have the size of accel').
    subroutine check_history_sizes(n, names, stat, errmsg, h1, h2, h3, h4)
        integer, intent(in) :: n                              !! samples of the record
        character(len=*), intent(in) :: names(4)              !! names of h1..h4 in messages
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> the histories (any unit); each absent one is not checked
        real(dp), intent(in), optional :: h1(:), h2(:), h3(:), h4(:)
        logical :: bad(4)
        integer :: k
        stat = SEISPULSE_SUCCESS
        bad = .false.
        if (present(h1)) bad(1) = size(h1) /= n
        if (present(h2)) bad(2) = size(h2) /= n
        if (present(h3)) bad(3) = size(h3) /= n
        if (present(h4)) bad(4) = size(h4) /= n
        do k = 1, 4
            if (bad(k)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, trim(names(k)) &
                               //': must have the size of accel')
                return
            end if
        end do
    end subroutine check_history_sizes

end module seispulse_checks
