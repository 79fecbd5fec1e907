!> One axis of a table (spectrum periods, frequency ratios, the grids of a map): a list
!> of values, or a range min, max with a count (and a spacing). One code path, so that
!> an axis is given and checked the same way in every analysis.
module driver_axis
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse, only: dp, shortest_str, outside, real_str, int_str
    use driver_namelist_scan, only: nml_group
    use driver_input, only: join, given, list_length, list_item, name_index, value_name
    implicit none
    private

    public :: axis_values

    character(len=6), parameter :: spacing_names(2) = [character(len=6) :: 'linear', 'log']

contains

    !> Values of one axis: a list `<lname>` (strictly ascending if `ascending`), or a range
    !> `<stem>_range` = min, max with `<stem>_count` points and `spacing` (linear | log;
    !> log needs min > 0). Values >= 0 (> 0 with `positive`). Neither given: no values
    !> (with `required`: the message that the list is missing). `grid` says how they were
    !> given (for the table header); errmsg (without the location) on failure. Keys not
    !> given in `group` are not checked.
    !>
    !> The map of analysis 'rocking' words its messages its own way: `real_numbers` names
    !> a list value always with its index and writes numbers with real_str (else the
    !> shortest form, num), `hint` = .false. leaves out what to give after "give only one
    !> of them", and `count_optional` lets `<stem>_count` keep its default with a range.
    subroutine axis_values(group, lname, stem, list, range, count, spacing, positive, &
                           ascending, max_count, values, grid, errmsg, required, &
                           count_optional, hint, real_numbers)
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
        logical, intent(in), optional :: required         !! neither given is an error
        logical, intent(in), optional :: count_optional   !! <stem>_count has a default
        logical, intent(in), optional :: hint             !! default .true.
        logical, intent(in), optional :: real_numbers     !! default .false.
        character(len=:), allocatable :: rname, cname, bound
        integer :: n, i, code
        real(dp) :: a, b
        logical :: must, any_count, say_what, plain

        must = .false.
        if (present(required)) must = required
        any_count = .false.
        if (present(count_optional)) any_count = count_optional
        say_what = .true.
        if (present(hint)) say_what = hint
        plain = .false.
        if (present(real_numbers)) plain = real_numbers
        errmsg = ''
        grid = ''
        rname = stem//'_range'
        cname = stem//'_count'
        bound = merge('> 0 ', '>= 0', positive)
        allocate(values(0))
        if (given(group, lname) .and. given(group, rname)) then
            errmsg = lname//', '//rname//': give only one of them'
            if (say_what) errmsg = errmsg//' (a list, or a range with '//cname//')'
            return
        end if
        if (must .and. .not. (given(group, lname) .or. given(group, rname))) then
            errmsg = lname//': missing (give '//lname//' = a list, or '//rname//' = min, ' &
                     //'max with '//cname//')'
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
                    if (plain) then
                        errmsg = list_item(lname, i)//' = '//real_str(list(i))
                    else
                        errmsg = value_name(lname, i, n)//' = '//shortest_str(list(i))
                    end if
                    errmsg = errmsg//': must be a finite number '//trim(bound)
                    return
                end if
            end do
            do i = 2, n
                if (.not. ascending) exit
                if (.not. list(i) > list(i - 1)) then
                    errmsg = list_item(lname, i)//' = '//number(list(i))//': the values ' &
                             //'must be strictly ascending'
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
                errmsg = list_item(rname, 1)//' = '//number(a)//': must be '//trim(bound)
                return
            end if
            if (.not. b > a) then
                errmsg = rname//' = '//number(a)//', '//number(b)//': the maximum must be ' &
                         //'above the minimum'
                return
            end if
            if (.not. (any_count .or. given(group, cname))) then
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
            grid = rname//' = '//shortest_str(a)//', '//shortest_str(b)//', '//cname//' = ' &
                //int_str(count) &
                   //', spacing = '''//trim(spacing_names(code))//''''
        end if

    contains

        !> x as the messages of this axis write numbers.
        function number(x) result(s)
            real(dp), intent(in) :: x
            character(len=:), allocatable :: s
            if (plain) then
                s = real_str(x)
            else
                s = shortest_str(x)
            end if
        end function number

    end subroutine axis_values

end module driver_axis
