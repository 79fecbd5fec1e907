!> Checks shared by every analysis: known groups, known keys, reading a group with an
!> error that names the file, line, group, key and problem, and how names and numbers
!> read in those messages.
module driver_input
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
    use seispulse, only: dp, shortest_str, real_str, int_str
    use, intrinsic :: iso_fortran_env, only: int64
    use driver_namelist_scan, only: nml_group, nml_item, lower, next_value
    implicit none
    private

    public :: group_reader, find_group, check_keys, read_group, located, join
    public :: read_optional, given, list_length, list_item, value_name, name_index
    public :: ROWS_FAILED, set_run_line, missing_group, located_key, output_located

    !> stat of an analysis that wrote its tables but failed some rows (a record that could
    !> not be read or analysed): the driver exits with status 1.
    integer, parameter :: ROWS_FAILED = -1

    abstract interface
        !> Read one namelist group into the analysis' variables: from `unit`, or
        !> from `text` (an internal file "&group key = value /") when it is not empty.
        subroutine group_reader(unit, text, ios, iomsg)
            integer, intent(in) :: unit
            character(len=*), intent(in) :: text
            integer, intent(out) :: ios
            character(len=*), intent(inout) :: iomsg
        end subroutine group_reader
    end interface

    !> Line of &run in the input file: a missing group is reported at it (the analysis
    !> that &run chose needs the group).
    integer :: run_line = 0

contains

    !> Remember the line of &run (for missing_group and output_located).
    subroutine set_run_line(line)
        integer, intent(in) :: line
        run_line = line
    end subroutine set_run_line

    !> "file:line: &name: missing group", the line that of &run.
    function missing_group(path, name) result(text)
        character(len=*), intent(in) :: path, name
        character(len=:), allocatable :: text
        text = path//':'//int_str(run_line)//': &'//name//': missing group'
    end function missing_group

    !> "file:line: &run: output: ", the start of a message about the output files (the
    !> line that of &run, whose `output` names them).
    function output_located(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        text = path//':'//int_str(run_line)//': &run: output: '
    end function output_located

    !> Index of group `name` in `groups`, 0 if absent.
    pure integer function find_group(groups, name)
        type(nml_group), intent(in) :: groups(:)
        character(len=*), intent(in) :: name
        integer :: i
        find_group = 0
        do i = 1, size(groups)
            if (groups(i)%name == name) then
                find_group = i
                return
            end if
        end do
    end function find_group

    !> Every key of `group` must be in `allowed`; each key at most once.
    subroutine check_keys(path, group, allowed, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: group
        character(len=*), intent(in) :: allowed(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: i, j
        stat = 0
        errmsg = ''
        do i = 1, size(group%items)
            if (.not. any(allowed == group%items(i)%key)) then
                stat = 1
                errmsg = located(path, group)//group%items(i)%key//': unknown key (allowed: ' &
                         //join(allowed)//')'
                return
            end if
            do j = 1, i - 1
                if (group%items(j)%key == group%items(i)%key) then
                    stat = 1
                    errmsg = located(path, group)//group%items(i)%key//': given twice'
                    return
                end if
            end do
        end do
    end subroutine check_keys

    !> Read group `groups(ig)` from `path` with `reader`. On a bad value, re-read each
    !> item alone to find the key it belongs to.
    subroutine read_group(path, group, reader, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: group
        procedure(group_reader) :: reader
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: u, ios, i
        character(len=512) :: iomsg
        errmsg = ''
        open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            stat = 1
            errmsg = path//': cannot open the input file: '//trim(iomsg)
            return
        end if
        iomsg = ''
        call reader(u, '', ios, iomsg)
        close(u)
        stat = 0
        if (ios == 0) return
        stat = 1
        do i = 1, size(group%items)
            iomsg = ''
            call reader(-1, '&'//group%name//' '//group%items(i)%text//' /', ios, iomsg)
            if (ios /= 0) then
                errmsg = located(path, group)//item_problem(group%name, group%items(i), &
                                                            reader, iomsg)
                return
            end if
        end do
        errmsg = located(path, group)//'cannot read the group ('//trim(iomsg)//')'
    end subroutine read_group

    !> What is wrong with an item that does not read alone: more values than its list
    !> holds ("ky: 1200 values, more than the list holds (1000)"), else "key: bad value
    !> in "key = ..." (the compiler's message)", the item cut after max_quoted characters.
    function item_problem(gname, item, reader, iomsg) result(text)
        character(len=*), intent(in) :: gname
        type(nml_item), intent(in) :: item
        procedure(group_reader) :: reader
        character(len=*), intent(in) :: iomsg
        character(len=:), allocatable :: text
        integer, parameter :: max_quoted = 100
        character(len=:), allocatable :: first
        character(len=512) :: msg
        integer :: nvalues, lo, hi, mid, ios, eq
        integer(int64) :: count
        text = item%key//': bad value in "'//item%text(1:min(len(item%text), max_quoted))
        if (len(item%text) > max_quoted) text = text//' ...'
        text = text//'" ('//trim(iomsg)//')'
        ! a list longer than its array: count the values, then find the size of the array
        ! (the largest subscript that reads, by bisection)
        eq = index(item%text, '=')
        if (eq == 0 .or. index(item%text(1:eq), '(') > 0) return
        call count_values(item%text(eq + 1:), count, first)
        if (count < 2 .or. len(first) == 0) return
        nvalues = int(min(count, int(huge(0), int64) - 1_int64))
        if (.not. reads(1)) return
        if (reads(nvalues)) return
        lo = 1
        hi = 2
        do while (hi < nvalues)
            if (.not. reads(hi)) exit
            lo = hi
            hi = 2 * hi
        end do
        hi = min(hi, nvalues)
        ! reads(lo), not reads(hi)
        do while (hi - lo > 1)
            mid = lo + (hi - lo) / 2
            if (reads(mid)) then
                lo = mid
            else
                hi = mid
            end if
        end do
        text = item%key//': '//int_str(nvalues)//' values, more than the list holds (' &
               //int_str(lo)//')'
    contains
        logical function reads(i)
            integer, intent(in) :: i
            msg = ''
            call reader(-1, '&'//gname//' '//item%key//'('//int_str(i)//') = '//first//' /', &
                        ios, msg)
            reads = ios == 0
        end function reads
    end function item_problem

    !> The number of values in namelist value text "v1, 3*v2 v3" (commas or blanks
    !> between them, outside quotes; r*v counts r) and the first value (without r*).
    subroutine count_values(text, count, first)
        character(len=*), intent(in) :: text
        integer(int64), intent(out) :: count
        character(len=:), allocatable, intent(out) :: first
        integer :: pos, start, last, star, reps, ios
        count = 0
        first = ''
        pos = 1
        do
            call next_value(text, pos, start, last)
            if (start == 0) exit
            reps = 1
            star = index(text(start:last), '*')
            if (star > 1) then
                if (verify(text(start:start + star - 2), '0123456789') == 0) then
                    read(text(start:start + star - 2), *, iostat=ios) reps
                    if (ios /= 0) reps = 1
                else
                    star = 0
                end if
            else
                star = 0
            end if
            if (count == 0) first = text(start + star:last)
            count = count + reps
        end do
    end subroutine count_values

    !> Check the keys of an optional group and read it; an empty group (line 0) if absent.
    subroutine read_optional(path, groups, name, keys, reader, group, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: name              !! group name
        character(len=*), intent(in) :: keys(:)           !! its allowed keys
        procedure(group_reader) :: reader
        type(nml_group), intent(out) :: group             !! the group, or an empty one
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: k
        stat = 0
        errmsg = ''
        k = find_group(groups, name)
        if (k == 0) then
            group%name = name
            group%line = 0
            allocate(group%items(0))
            return
        end if
        group = groups(k)
        call check_keys(path, group, keys, stat, errmsg)
        if (stat /= 0) return
        call read_group(path, group, reader, stat, errmsg)
    end subroutine read_optional

    !> Whether `key` was written in `group`.
    pure logical function given(group, key)
        type(nml_group), intent(in) :: group
        character(len=*), intent(in) :: key
        integer :: i
        given = .false.
        do i = 1, size(group%items)
            if (group%items(i)%key == key) then
                given = .true.
                return
            end if
        end do
    end function given

    !> Number of values given in a list key (defaults NaN): the last value that is not
    !> NaN ends it; a NaN before it is a gap, an error.
    subroutine list_length(list, name, n, errmsg)
        real(dp), intent(in) :: list(:)
        character(len=*), intent(in) :: name
        integer, intent(out) :: n
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: i
        errmsg = ''
        n = 0
        do i = size(list), 1, -1
            if (.not. ieee_is_nan(list(i))) then
                n = i
                exit
            end if
        end do
        if (n == 0) then
            errmsg = name//': no value given'
            return
        end if
        do i = 1, n
            if (ieee_is_nan(list(i))) then
                errmsg = list_item(name, i)//': missing or NaN (give every value, ' &
                         //'without gaps)'
                return
            end if
        end do
    end subroutine list_length

    !> "name(i)".
    pure function list_item(name, i) result(item)
        character(len=*), intent(in) :: name
        integer, intent(in) :: i
        character(len=:), allocatable :: item
        item = name//'('//int_str(i)//')'
    end function list_item

    !> "name" for a single value, "name(i)" in a list of n.
    pure function value_name(name, i, n) result(item)
        character(len=*), intent(in) :: name
        integer, intent(in) :: i, n
        character(len=:), allocatable :: item
        if (n > 1) then
            item = list_item(name, i)
        else
            item = name
        end if
    end function value_name

    !> Index of a name (case and leading blanks ignored) in `names`, 0 if absent.
    pure integer function name_index(text, names)
        character(len=*), intent(in) :: text
        character(len=*), intent(in) :: names(:)
        integer :: i
        name_index = 0
        do i = 1, size(names)
            if (trim(lower(adjustl(text))) == trim(names(i))) then
                name_index = i
                return
            end if
        end do
    end function name_index

    !> "file:line: &group: " prefix of a message.
    function located(path, group) result(prefix)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: group
        character(len=:), allocatable :: prefix
        character(len=16) :: num
        write(num, '(i0)') group%line
        prefix = path//':'//trim(num)//': &'//group%name//': '
    end function located

    !> "file:line: &group: " + msg for a message of the library that starts with a key
    !> name ("beta_deg = 30.0: ..."): the group of `candidates` that gave that key, else
    !> the first of them.
    function located_key(path, candidates, msg) result(text)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: candidates(:)
        character(len=*), intent(in) :: msg
        character(len=:), allocatable :: text
        integer :: i, k
        k = verify(msg, 'abcdefghijklmnopqrstuvwxyz0123456789_') - 1
        if (k < 0) k = len(msg)
        do i = 1, size(candidates)
            if (k > 0) then
                if (given(candidates(i), msg(1:k))) then
                    text = located(path, candidates(i))//msg
                    return
                end if
            end if
        end do
        text = located(path, candidates(1))//msg
    end function located_key

    !> "a, b, c" from a list of names.
    pure function join(names) result(list)
        character(len=*), intent(in) :: names(:)
        character(len=:), allocatable :: list
        integer :: i
        list = ''
        do i = 1, size(names)
            if (i > 1) list = list//', '
            list = list//trim(names(i))
        end do
    end function join

end module driver_input
