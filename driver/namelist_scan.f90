!> Pre-scan of a namelist file, so that errors name the group and the key.
!>
!> Fortran's namelist READ skips groups it was not asked for and reports a bad
!> value as "Cannot match namelist object name <value>". Scanning the text first
!> lets the driver reject unknown groups and keys by name, and pin a bad value on
!> its key by re-reading each "key = value" item alone from an internal file.
module driver_namelist_scan
    use, intrinsic :: iso_fortran_env, only: int64
    use seispulse, only: int_str
    use driver_paths, only: path_kind, PATH_NONE, PATH_DIR, PATH_OTHER
    implicit none
    private

    public :: nml_item, nml_group, scan_file, scan_unit, lower, read_line, control_char, &
              char_name, text_buffer, append, contents, next_value, unreadable, &
              open_text
    public :: max_line_len, max_input_len, max_groups, max_items

    !> Longest line of an input file (characters): a longer one is not a namelist input.
    integer, parameter :: max_line_len = 262144
    !> Longest input file (characters, with the ends of lines).
    integer, parameter :: max_input_len = 8 * 1048576
    !> Most groups in an input file, and items (key = value) in one group.
    integer, parameter :: max_groups = 1000, max_items = 100000

    !> A text that grows by `append` (capacity doubled when full); `contents` is its text.
    type :: text_buffer
        character(len=:), allocatable :: s   !! storage: the text is s(1:n)
        integer :: n = 0                     !! length of the text
    end type text_buffer

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
    !> "file:line: ...") if the file cannot be read, is not a text file (a NUL or another
    !> control character), has a line longer than max_line_len or is longer than
    !> max_input_len characters, or a group is not closed with '/'.
    subroutine scan_file(path, groups, stat, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), allocatable, intent(out) :: groups(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: u

        stat = 1
        allocate(groups(0))
        call open_text(path, 'input file', u, errmsg)
        if (len(errmsg) > 0) return
        deallocate(groups)
        call scan_unit(u, groups, stat, errmsg, checked=.true.)
        close(u)
        if (stat /= 0) errmsg = path//':'//errmsg
    end subroutine scan_file

    !> scan_file on a unit open for reading, from its current position to its end. With
    !> `checked`, the text must be a text file within the limits of scan_file (errors
    !> "<line>: ..."); without it lines of any length are read.
    subroutine scan_unit(u, groups, stat, errmsg, checked)
        integer, intent(in) :: u
        type(nml_group), allocatable, intent(out) :: groups(:)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        logical, intent(in), optional :: checked
        character(len=:), allocatable :: line
        type(text_buffer) :: body
        type(nml_group), allocatable :: found(:)
        character(len=512) :: iomsg
        integer :: ios, lineno, i, start_line, ngroups, max_len, bad, nline, item_cap
        integer(int64) :: total
        logical :: in_group, check, too_long
        character :: quote

        check = .false.
        if (present(checked)) check = checked
        max_len = huge(0)
        if (check) max_len = max_line_len
        item_cap = huge(0) - 1
        if (check) item_cap = max_items
        allocate(found(8))
        ngroups = 0
        errmsg = ''
        stat = 0
        in_group = .false.
        quote = ' '
        lineno = 0
        total = 0
        start_line = 0
        do
            call read_line(u, line, ios, max_len, too_long)
            if (ios /= 0) exit
            lineno = lineno + 1
            if (check) then
                if (too_long) then
                    stat = 1
                    errmsg = int_str(lineno)//': line longer than '//int_str(max_line_len) &
                             //' characters (not a namelist input file?)'
                    exit
                end if
                bad = control_char(line)
                if (bad > 0) then
                    stat = 1
                    errmsg = int_str(lineno)//': '//char_name(line(bad:bad))//' at column ' &
                             //int_str(bad)//': not a text file (a namelist input is text)'
                    exit
                end if
                total = total + len(line) + 1
                if (total > max_input_len) then
                    stat = 1
                    errmsg = int_str(lineno)//': the input is longer than ' &
                             //int_str(max_input_len)//' characters (not a namelist ' &
                             //'input file?)'
                    exit
                end if
            end if
            i = 0
            nline = len_trim(line)
            do while (i < nline)
                i = i + 1
                if (quote /= ' ') then
                    if (in_group) call append(body, line(i:i))
                    if (line(i:i) == quote) quote = ' '
                    cycle
                end if
                select case (line(i:i))
                case ('!')
                    exit
                case ('''', '"')
                    quote = line(i:i)
                    if (in_group) call append(body, line(i:i))
                case ('&', '$')
                    if (.not. in_group) then
                        in_group = .true.
                        start_line = lineno
                        body%n = 0
                    else
                        call append(body, line(i:i))
                    end if
                case ('/')
                    if (in_group) then
                        if (check .and. ngroups == max_groups) then
                            stat = 1
                            errmsg = int_str(start_line)//': more than '//int_str(max_groups) &
                                     //' groups (not a namelist input file?)'
                            exit
                        end if
                        call add_group(found, ngroups, contents(body), start_line, item_cap)
                        in_group = .false.
                        if (check .and. size(found(ngroups)%items) > max_items) then
                            stat = 1
                            errmsg = int_str(start_line)//': &'//found(ngroups)%name &
                                     //': more than '//int_str(max_items)//' items ' &
                                     //'(key = value) in the group'
                            exit
                        end if
                    end if
                case default
                    if (in_group) call append(body, line(i:i))
                end select
            end do
            if (stat /= 0) exit
            if (in_group) call append(body, ' ')
        end do
        groups = found(1:ngroups)
        if (stat /= 0) return
        if (in_group) then
            stat = 1
            ! "<line>: &<name>: ..." (the caller puts the file in front)
            line = contents(body)
            i = verify(line, ' ')
            if (i == 0) i = len(line) + 1
            write(iomsg, '(i0, a)') start_line, ': &'//lower(line(i:i - 1 + min(64, &
                max(0, scan(line(i:)//' ', ' ') - 1))))//': not closed with / (the group ' &
                //'starts here)'
            errmsg = trim(iomsg)
        end if
    end subroutine scan_unit

    !> The next value of namelist value text ("a, b c ,d": separated by commas and blanks
    !> outside quotes) from position pos: text(a:b), a = 0 when there is none; pos moves
    !> past it.
    pure subroutine next_value(text, pos, a, b)
        character(len=*), intent(in) :: text
        integer, intent(inout) :: pos
        integer, intent(out) :: a, b
        integer :: i
        character :: q
        a = 0
        b = 0
        q = ' '
        do i = pos, len(text) + 1
            if (i <= len(text)) then
                if (q /= ' ') then
                    if (text(i:i) == q) q = ' '
                    cycle
                end if
                if (text(i:i) == '"' .or. text(i:i) == '''') then
                    q = text(i:i)
                    if (a == 0) a = i
                    cycle
                end if
                if (text(i:i) /= ',' .and. text(i:i) /= ' ') then
                    if (a == 0) a = i
                    cycle
                end if
            end if
            if (a > 0) then
                b = i - 1
                pos = i + 1
                return
            end if
        end do
        pos = len(text) + 2
    end subroutine next_value

    !> Open `path` for reading as a text file on a new unit u ("what": 'input file', 'list
    !> file', for the messages); errmsg: '' or why not (unreadable, or the open's message).
    subroutine open_text(path, what, u, errmsg)
        character(len=*), intent(in) :: path, what
        integer, intent(out) :: u
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: iomsg
        integer :: ios
        u = -1
        errmsg = unreadable(path, what)
        if (len(errmsg) > 0) return
        open(newunit=u, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
        if (ios /= 0) errmsg = path//': cannot open the '//what//': '//trim(iomsg)
    end subroutine open_text

    !> What keeps `path` from being read as a text file: '' if nothing, else "path: is a
    !> directory, not a list file" (what = 'list file'), "path: cannot open the list
    !> file: no such file ...", "path: not a regular file ...".
    function unreadable(path, what) result(msg)
        character(len=*), intent(in) :: path, what
        character(len=:), allocatable :: msg
        msg = ''
        select case (path_kind(path))
        case (PATH_NONE)
            msg = path//': cannot open the '//what//': no such file (or it cannot be reached)'
        case (PATH_DIR)
            if (index('aeiou', what(1:1)) > 0) then
                msg = path//': is a directory, not an '//what
            else
                msg = path//': is a directory, not a '//what
            end if
        case (PATH_OTHER)
            msg = path//': not a regular file (a device, a pipe or a socket)'
        end select
    end function unreadable

    !> One line (non-advancing reads of 512-character chunks into a buffer that doubles);
    !> ios /= 0 at the end of the file. A line longer than max_len is cut there with
    !> too_long (the rest of it is not read).
    subroutine read_line(u, line, ios, max_len, too_long)
        integer, intent(in) :: u
        character(len=:), allocatable, intent(out) :: line
        integer, intent(out) :: ios
        integer, intent(in) :: max_len
        logical, intent(out) :: too_long
        character(len=512) :: chunk
        type(text_buffer) :: buf
        integer :: got
        too_long = .false.
        do
            read(u, '(a)', advance='no', iostat=ios, size=got) chunk
            call append(buf, chunk(1:got))
            if (ios /= 0) exit
            if (buf%n > max_len) then
                too_long = .true.
                exit
            end if
        end do
        line = contents(buf)
        ! a last line without a newline still counts
        if (is_iostat_eor(ios) .or. (is_iostat_end(ios) .and. len(line) > 0)) ios = 0
    end subroutine read_line

    !> Position of the first control character of s (not a tab or a carriage return), 0
    !> if none.
    pure integer function control_char(s)
        character(len=*), intent(in) :: s
        integer :: i, ic
        control_char = 0
        do i = 1, len(s)
            ic = iachar(s(i:i))
            if ((ic < 32 .and. ic /= 9 .and. ic /= 13) .or. ic == 127) then
                control_char = i
                return
            end if
        end do
    end function control_char

    !> "a NUL byte", "control character 27".
    pure function char_name(c) result(s)
        character, intent(in) :: c
        character(len=:), allocatable :: s
        if (iachar(c) == 0) then
            s = 'a NUL byte'
        else
            s = 'control character '//int_str(iachar(c))
        end if
    end function char_name

    ! ------------------------------------------------------------------------------
    ! A text that grows by appending (capacity doubled: linear time in its length)
    ! ------------------------------------------------------------------------------

    !> Append s to b.
    pure subroutine append(b, s)
        type(text_buffer), intent(inout) :: b
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: bigger
        integer :: cap
        if (len(s) == 0) return
        if (.not. allocated(b%s)) allocate(character(len=max(256, len(s))) :: b%s)
        if (b%n + len(s) > len(b%s)) then
            cap = len(b%s)
            do while (cap < b%n + len(s))
                cap = 2 * cap
            end do
            allocate(character(len=cap) :: bigger)
            bigger(1:b%n) = b%s(1:b%n)
            call move_alloc(bigger, b%s)
        end if
        b%s(b%n + 1:b%n + len(s)) = s
        b%n = b%n + len(s)
    end subroutine append

    !> The text of b.
    pure function contents(b) result(s)
        type(text_buffer), intent(in) :: b
        character(len=:), allocatable :: s
        if (b%n == 0) then
            s = ''
        else
            s = b%s(1:b%n)
        end if
    end function contents

    !> Split "name key = value, key = value ..." into the group name and items: the group
    !> groups(ngroups + 1) (the array doubled when full). After max_items items the rest
    !> of the body is one more item.
    subroutine add_group(groups, ngroups, body, line, max_items)
        type(nml_group), allocatable, intent(inout) :: groups(:)
        integer, intent(inout) :: ngroups
        character(len=*), intent(in) :: body
        integer, intent(in) :: line
        integer, intent(in) :: max_items
        type(nml_group), allocatable :: more(:)
        integer :: i, j, n, name_end, eq, key_start, k, prev_eq, item_start, neq, last_eq
        integer, allocatable :: eqs(:), keys(:)
        character :: quote

        if (ngroups == size(groups)) then
            allocate(more(2 * size(groups)))
            more(1:ngroups) = groups(1:ngroups)
            call move_alloc(more, groups)
        end if
        ngroups = ngroups + 1
        n = len(body)
        name_end = 1
        do while (name_end <= n)
            if (is_space(body(name_end:name_end))) exit
            name_end = name_end + 1
        end do
        groups(ngroups)%name = lower(body(1:name_end - 1))
        groups(ngroups)%line = line
        ! positions of '=' outside quotes, and where the key before each one starts (the
        ! searches backwards stop at the '=' before: linear time)
        allocate(eqs(16), keys(16))
        neq = 0
        last_eq = name_end
        quote = ' '
        do i = name_end, n
            if (quote /= ' ') then
                if (body(i:i) == quote) quote = ' '
            else if (body(i:i) == '''' .or. body(i:i) == '"') then
                quote = body(i:i)
            else if (body(i:i) == '=') then
                eq = i
                k = eq - 1
                do while (k > last_eq)
                    if (.not. is_space(body(k:k))) exit
                    k = k - 1
                end do
                ! key (with an optional subscript) ends at k
                if (body(k:k) == ')') then
                    j = k
                    do while (j > last_eq .and. body(j:j) /= '(')
                        j = j - 1
                    end do
                    ! no '(' since the '=' before: the ')' is part of the (bad) key
                    if (body(j:j) == '(') k = j - 1
                end if
                key_start = max(k, 1)
                do while (key_start > last_eq)
                    if (.not. is_name_char(body(key_start - 1:key_start - 1))) exit
                    key_start = key_start - 1
                end do
                if (neq == size(eqs)) then
                    eqs = [eqs, eqs]
                    keys = [keys, keys]
                end if
                neq = neq + 1
                eqs(neq) = eq
                keys(neq) = key_start
                last_eq = eq
                if (neq > max_items) exit
            end if
        end do
        allocate(groups(ngroups)%items(neq))
        do i = 1, neq
            associate (item => groups(ngroups)%items(i))
                item_start = keys(i)
                if (i < neq) then
                    prev_eq = keys(i + 1) - 1
                else
                    prev_eq = n
                end if
                k = index(body(item_start:eqs(i)), '(')
                if (k > 0) then
                    item%key = lower(adjustl(body(item_start:item_start + k - 2)))
                else
                    item%key = lower(trim(adjustl(body(item_start:eqs(i) - 1))))
                end if
                item%key = trim(item%key)
                item%text = trim(strip_comma(body(item_start:prev_eq)))
            end associate
        end do
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
