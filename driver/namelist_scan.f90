!> Pre-scan of a namelist file, so that errors name the group and the key.
!>
!> Fortran's namelist READ skips groups it was not asked for and reports a bad
!> value as "Cannot match namelist object name <value>". Scanning the text first
!> lets the driver reject unknown groups and keys by name, and pin a bad value on
!> its key by re-reading each "key = value" item alone from an internal file.
module driver_namelist_scan
    implicit none
    private

    public :: nml_item, nml_group, scan_file, scan_unit, lower

    !> One "key = value" item of a group, as written.
    type :: nml_item
        character(len=:), allocatable :: key    !! lower case, without subscripts
        character(len=:), allocatable :: text   !! "key = value" as in the file
    end type nml_item

    !> One group: its name, the line it starts on, and its items.
    type :: nml_group
        character(len=:), allocatable :: name   !! lower case, without '&'
        integer :: line = 0                     !! line of the '&name'
        type(nml_item), allocatable :: items(:)
    end type nml_group

contains

    !> Read `path` and split it into groups and items. Comments (! to end of line,
    !> outside quotes) are dropped. stat /= 0 with a message ("file: ..." or
    !> "file:line: &group: ...") if the file cannot be read or a group is not closed
    !> with '/'.
    subroutine scan_file(path, groups, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), allocatable, intent(out) :: groups(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: iomsg
        integer :: u, ios

        open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            allocate(groups(0))
            stat = 1
            errmsg = path//': cannot open the input file: '//trim(iomsg)
            return
        end if
        call scan_unit(u, groups, stat, errmsg)
        close(u)
        if (stat /= 0) errmsg = path//':'//errmsg
    end subroutine scan_file

    !> scan_file on a unit open for reading, from its current position to its end (lines
    !> of any length).
    subroutine scan_unit(u, groups, stat, errmsg)
        integer, intent(in) :: u
        type(nml_group), allocatable, intent(out) :: groups(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: line
        character(len=:), allocatable :: body
        character(len=512) :: iomsg
        integer :: ios, lineno, i, start_line
        logical :: in_group
        character :: quote

        allocate(groups(0))
        errmsg = ''
        stat = 0
        in_group = .false.
        quote = ' '
        lineno = 0
        body = ''
        start_line = 0
        do
            call read_line(u, line, ios)
            if (ios /= 0) exit
            lineno = lineno + 1
            i = 0
            do while (i < len_trim(line))
                i = i + 1
                if (quote /= ' ') then
                    if (in_group) body = body//line(i:i)
                    if (line(i:i) == quote) quote = ' '
                    cycle
                end if
                select case (line(i:i))
                case ('!')
                    exit
                case ('''', '"')
                    quote = line(i:i)
                    if (in_group) body = body//line(i:i)
                case ('&', '$')
                    if (.not. in_group) then
                        in_group = .true.
                        start_line = lineno
                        body = ''
                    else
                        body = body//line(i:i)
                    end if
                case ('/')
                    if (in_group) then
                        call add_group(groups, body, start_line)
                        in_group = .false.
                    end if
                case default
                    if (in_group) body = body//line(i:i)
                end select
            end do
            if (in_group) body = body//' '
        end do
        if (in_group) then
            stat = 1
            ! "<line>: &<name>: ..." (the caller puts the file in front)
            i = verify(body, ' ')
            if (i == 0) i = len(body) + 1
            write(iomsg, '(i0, a)') start_line, ': &'//lower(body(i:i - 1 + max(0, &
                scan(body(i:)//' ', ' ') - 1)))//': not closed with / (the group starts here)'
            errmsg = trim(iomsg)
        end if
    end subroutine scan_unit

    !> One line of any length (non-advancing reads of 512-character chunks); ios /= 0 at
    !> the end of the file.
    subroutine read_line(u, line, ios)
        integer, intent(in) :: u
        character(len=:), allocatable, intent(out) :: line
        integer, intent(out) :: ios
        character(len=512) :: chunk
        integer :: got
        line = ''
        do
            read(u, '(a)', advance='no', iostat=ios, size=got) chunk
            line = line//chunk(1:got)
            if (ios /= 0) exit
        end do
        ! a last line without a newline still counts
        if (is_iostat_eor(ios) .or. (is_iostat_end(ios) .and. len(line) > 0)) ios = 0
    end subroutine read_line

    !> Split "name key = value, key = value ..." into the group name and items.
    subroutine add_group(groups, body, line)
        type(nml_group), allocatable, intent(inout) :: groups(:)
        character(len=*), intent(in) :: body
        integer, intent(in) :: line
        type(nml_group) :: g
        integer :: i, n, name_end, eq, key_start, k, prev_eq, item_start
        integer, allocatable :: eqs(:), keys(:)
        character :: quote

        n = len(body)
        name_end = 1
        do while (name_end <= n)
            if (is_space(body(name_end:name_end))) exit
            name_end = name_end + 1
        end do
        g%name = lower(body(1:name_end - 1))
        g%line = line
        ! positions of '=' outside quotes, and where the key before each one starts
        allocate(eqs(0), keys(0))
        quote = ' '
        do i = name_end, n
            if (quote /= ' ') then
                if (body(i:i) == quote) quote = ' '
            else if (body(i:i) == '''' .or. body(i:i) == '"') then
                quote = body(i:i)
            else if (body(i:i) == '=') then
                eq = i
                k = eq - 1
                do while (k > name_end)
                    if (.not. is_space(body(k:k))) exit
                    k = k - 1
                end do
                ! key (with an optional subscript) ends at k
                if (body(k:k) == ')') then
                    do while (k > name_end .and. body(k:k) /= '(')
                        k = k - 1
                    end do
                    k = k - 1
                end if
                key_start = k
                do while (key_start > name_end)
                    if (.not. is_name_char(body(key_start - 1:key_start - 1))) exit
                    key_start = key_start - 1
                end do
                eqs = [eqs, eq]
                keys = [keys, key_start]
            end if
        end do
        allocate(g%items(size(eqs)))
        do i = 1, size(eqs)
            item_start = keys(i)
            if (i < size(eqs)) then
                prev_eq = keys(i + 1) - 1
            else
                prev_eq = n
            end if
            k = index(body(item_start:eqs(i)), '(')
            if (k > 0) then
                g%items(i)%key = lower(adjustl(body(item_start:item_start + k - 2)))
            else
                g%items(i)%key = lower(trim(adjustl(body(item_start:eqs(i) - 1))))
            end if
            g%items(i)%key = trim(g%items(i)%key)
            g%items(i)%text = trim(strip_comma(body(item_start:prev_eq)))
        end do
        groups = [groups, g]
    end subroutine add_group

    pure function strip_comma(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: k
        k = len_trim(s)
        do while (k > 0)
            if (s(k:k) /= ',' .and. .not. is_space(s(k:k))) exit
            k = k - 1
        end do
        r = s(1:k)
    end function strip_comma

    pure logical function is_space(c)
        character, intent(in) :: c
        is_space = c == ' ' .or. iachar(c) == 9 .or. iachar(c) == 13
    end function is_space

    pure logical function is_name_char(c)
        character, intent(in) :: c
        is_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') &
                       .or. (c >= '0' .and. c <= '9') .or. c == '_'
    end function is_name_char

    !> Lower-case copy of s.
    pure function lower(s) result(r)
        character(len=*), intent(in) :: s
        character(len=len(s)) :: r
        integer :: i, ic
        r = s
        do i = 1, len(s)
            ic = iachar(s(i:i))
            if (ic >= iachar('A') .and. ic <= iachar('Z')) r(i:i) = achar(ic + 32)
        end do
    end function lower

end module driver_namelist_scan
