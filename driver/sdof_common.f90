!> What the analyses of the linear oscillator ('sdof', 'sdof_beta', 'sdof_shock') share:
!> the limits of their lists, the damping ratios of a `damping` key and the values of an
!> axis given as a list or as a range with a count.
module driver_sdof_common
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: outside
    use seispulse_format, only: int_str
    use driver_namelist_scan, only: nml_group
    use driver_input, only: join, given, list_length, list_item, name_index, value_name, num
    implicit none
    private

    public :: max_periods, max_dampings, check_dampings, axis_values

    character(len=6), parameter :: spacing_names(2) = [character(len=6) :: 'linear', 'log']

    !> Most periods (list or range), most damping ratios.
    integer, parameter :: max_periods = 1000, max_dampings = 100
    !> Damping ratio when none is given.
    real(dp), parameter :: default_damping = 0.05_dp

contains

    !> The damping ratios of a `damping` list (default_damping when not given): each
    !> finite, in [0, 1). errmsg (without the location) on failure.
    subroutine check_dampings(group, list, values, errmsg)
        type(nml_group), intent(in) :: group
        real(dp), intent(in) :: list(:)
        real(dp), allocatable, intent(out) :: values(:)
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: n, i
        errmsg = ''
        if (.not. given(group, 'damping')) then
            values = [default_damping]
            return
        end if
        call list_length(list, 'damping', n, errmsg)
        if (len(errmsg) > 0) return
        do i = 1, n
            if (outside(list(i), 0.0_dp, 1.0_dp, .false., .true.)) then
                errmsg = value_name('damping', i, n)//' = '//num(list(i))//': must be a ' &
                         //'damping ratio in [0, 1)'
                return
            end if
        end do
        values = list(1:n)
    end subroutine check_dampings

    !> Values of one axis: a list `<lname>` (strictly ascending if `ascending`), or a range
    !> `<stem>_range` = min, max with `<stem>_count` points and `spacing` (linear | log;
    !> log needs min > 0). Values >= 0 (> 0 with `positive`). Neither given: no values.
    !> `grid` says how they were given (for the table header); errmsg (without the
    !> location) on failure. Keys not given in `group` are not checked.
    subroutine axis_values(group, lname, stem, list, range, count, spacing, positive, &
                           ascending, max_count, values, grid, errmsg)
        type(nml_group), intent(in) :: group
        character(len=*), intent(in) :: lname             !! name of the list key
        character(len=*), intent(in) :: stem              !! stem of <stem>_range, <stem>_count
        real(dp), intent(in) :: list(:), range(2)
        integer, intent(in) :: count
        character(len=*), intent(in) :: spacing
        logical, intent(in) :: positive                   !! values > 0 (else >= 0)
        logical, intent(in) :: ascending                  !! a list must be strictly ascending
        integer, intent(in) :: max_count
        real(dp), allocatable, intent(out) :: values(:)
        character(len=:), allocatable, intent(out) :: grid
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: rname, cname, bound
        integer :: n, i, code
        real(dp) :: a, b

        errmsg = ''
        grid = ''
        rname = stem//'_range'
        cname = stem//'_count'
        bound = merge('> 0 ', '>= 0', positive)
        allocate(values(0))
        if (given(group, lname) .and. given(group, rname)) then
            errmsg = lname//', '//rname//': give only one of them (a list, or a range with ' &
                     //cname//')'
            return
        end if
        if (.not. given(group, rname)) then
            if (given(group, cname)) then
                errmsg = cname//': only with '//rname
                return
            else if (given(group, 'spacing')) then
                errmsg = 'spacing: only with '//rname
                return
            end if
        end if
        if (given(group, lname)) then
            call list_length(list, lname, n, errmsg)   ! no gaps, at least one value
            if (len(errmsg) > 0) return
            do i = 1, n
                if (outside(list(i), 0.0_dp, huge(a), positive, .false.)) then
                    errmsg = value_name(lname, i, n)//' = '//num(list(i))//': must be a ' &
                             //'finite number '//trim(bound)
                    return
                end if
            end do
            do i = 2, n
                if (.not. ascending) exit
                if (.not. list(i) > list(i - 1)) then
                    errmsg = list_item(lname, i)//' = '//num(list(i))//': the values must ' &
                             //'be strictly ascending'
                    return
                end if
            end do
            values = list(1:n)
            grid = lname//' as listed'
        else if (given(group, rname)) then
            if (.not. (ieee_is_finite(range(1)) .and. ieee_is_finite(range(2)))) then
                errmsg = rname//': give two finite numbers, '//rname//' = min, max'
                return
            end if
            a = range(1)
            b = range(2)
            if (outside(a, 0.0_dp, huge(a), positive, .false.)) then
                errmsg = list_item(rname, 1)//' = '//num(a)//': must be '//trim(bound)
                return
            end if
            if (.not. b > a) then
                errmsg = rname//' = '//num(a)//', '//num(b)//': the maximum must be above ' &
                         //'the minimum'
                return
            end if
            if (.not. given(group, cname)) then
                errmsg = cname//': missing (the number of values in '//rname//', 2 .. ' &
                         //int_str(max_count)//')'
                return
            end if
            if (count < 2 .or. count > max_count) then
                errmsg = cname//' = '//int_str(count)//': must be in 2 .. '//int_str(max_count)
                return
            end if
            code = name_index(spacing, spacing_names)
            if (code == 0) then
                errmsg = 'spacing = '''//trim(spacing)//''': unknown spacing (allowed: ' &
                         //join(spacing_names)//')'
                return
            end if
            if (code == 2 .and. .not. a > 0.0_dp) then
                errmsg = 'spacing = ''log'': needs '//list_item(rname, 1)//' > 0 (use ' &
                         //'''linear'', or a list '//lname//' that starts with 0)'
                return
            end if
            deallocate(values)
            allocate(values(count))
            do i = 1, count
                if (code == 1) then
                    values(i) = a + (b - a) * (real(i - 1, dp) / real(count - 1, dp))
                else
                    values(i) = exp(log(a) + (log(b) - log(a)) * (real(i - 1, dp) &
                                                                 / real(count - 1, dp)))
                end if
            end do
            values(1) = a
            values(count) = b
            grid = rname//' = '//num(a)//', '//num(b)//', '//cname//' = '//int_str(count) &
                   //', spacing = '''//trim(spacing_names(code))//''''
        end if
    end subroutine axis_values

end module driver_sdof_common
