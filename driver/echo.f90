!> The echo of the effective input: one generic filter for every group.
!>
!> Each analysis writes its groups as read and completed with `write(echo_unit(),
!> nml=group)` (values of the keys as the analysis uses them). At the end of the run
!> `echo_finish` reads that text back and keeps, for each group of the input, the keys
!> the input gave (a key the analysis does not echo, such as a range it echoes as a
!> list, as the input wrote it); trailing NaN or blank values of an array are dropped,
!> strings trimmed, reals written as the shortest decimal that reads back to the same
!> double. The result is a valid namelist that re-runs the same analysis: the file
!> table_path(prefix, 'input', 'nml'), and standard output too with `verbose = .true.`
!> in &run. File names in the echo (the record files of &records) are rewritten
!> relative to the directory of the echo file.
module driver_echo
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use seispulse, only: dp, shortest_str, int_str
    use driver_namelist_scan, only: nml_group, scan_unit, lower, text_buffer, append, contents, &
                                    next_value
    use driver_input, only: find_group, given
    use driver_tables, only: table_path, open_output
    use driver_parallel, only: par_root
    implicit none
    private

    public :: echo_unit, echo_path, echo_start, echo_finish, echo_file_path

    !> One value of an item, as text.
    type :: string_t
        character(len=:), allocatable :: s
    end type string_t

    !> Lines of the echo file are broken after this many characters (between values).
    integer, parameter :: line_len = 90

    integer :: unit = 0                            !! the scratch file of the raw echo
    logical :: opened = .false.                    !! whether it is open
    character(len=:), allocatable :: echo_dir      !! directory of the echo file ('' = .)

contains

    !> Where the echo file of `prefix` goes: table_path(prefix, 'input', 'nml').
    function echo_file_path(prefix) result(path)
        character(len=*), intent(in) :: prefix   !! output prefix of &run
        character(len=:), allocatable :: path
        path = table_path(prefix, 'input', 'nml')
    end function echo_file_path

    !> Before the first group is echoed: the output prefix, whose directory file names in
    !> the echo are made relative to.
    subroutine echo_start(prefix)
        character(len=*), intent(in) :: prefix   !! output prefix of &run
        character(len=:), allocatable :: path
        integer :: k
        path = echo_file_path(prefix)
        k = index(path, '/', back=.true.)
        echo_dir = ''
        if (k > 0) echo_dir = path(1:k - 1)
        if (k == 1) echo_dir = '/'
    end subroutine echo_start

    !> The unit the groups are echoed to (a scratch file, opened on the first call).
    integer function echo_unit()
        if (.not. opened) open(newunit=unit, status='scratch', action='readwrite', &
                               form='formatted', delim='quote')
        opened = .true.
        echo_unit = unit
    end function echo_unit

    !> A file name as opened by the driver (relative to the working directory, or
    !> absolute), relative to the directory of the echo file, so that the echo file reads
    !> the same file wherever it lies. Absolute names stay; if the way from the echo
    !> directory back to the working directory is unknown (".." in it), the name is made
    !> absolute with $PWD when that is set.
    function echo_path(opened) result(path)
        character(len=*), intent(in) :: opened
        character(len=:), allocatable :: path, rest, dir, first, cwd
        integer :: k, depth, n, st
        path = opened
        if (.not. allocated(echo_dir)) return
        if (len(opened) == 0) return
        if (opened(1:1) == '/') return
        dir = echo_dir
        rest = opened
        do while (starts_with(rest, './'))
            rest = rest(3:)
        end do
        k = index(rest, '/./')
        do while (k > 0)
            rest = rest(1:k)//rest(k + 3:)
            k = index(rest, '/./')
        end do
        if (len(dir) == 0 .or. dir == '.') then
            path = rest
            return
        end if
        if (dir(1:1) == '/' .or. has_dotdot(dir)) then
            call get_environment_variable('PWD', length=n, status=st)
            if (st /= 0 .or. n == 0) return
            allocate(character(len=n) :: cwd)
            call get_environment_variable('PWD', cwd)
            path = cwd//'/'//rest
            return
        end if
        ! drop the leading components shared by dir and the name, then climb the rest
        depth = 0
        do while (len(dir) > 0)
            k = index(dir, '/')
            if (k == 0) then
                first = dir
                dir = ''
            else
                first = dir(1:k - 1)
                dir = dir(k + 1:)
            end if
            if (first == '.' .or. len(first) == 0) cycle
            if (depth == 0 .and. starts_with(rest, first//'/')) then
                rest = rest(len(first) + 2:)
            else
                depth = depth + 1
            end if
        end do
        path = repeat('../', depth)//rest
    end function echo_path

    !> Write the echo: the file (when `to_file`) and standard output (when `to_stdout`);
    !> nothing on a rank other than the root of an MPI job.
    !> `groups` are the groups of the input file (keys given there are kept even when
    !> their value is NaN or blank).
    subroutine echo_finish(input, groups, prefix, to_file, to_stdout, stat, errmsg)
        character(len=*), intent(in) :: input           !! the input file (for the header)
        type(nml_group), intent(in) :: groups(:)        !! groups of the input file
        character(len=*), intent(in) :: prefix          !! output prefix of &run
        logical, intent(in) :: to_file, to_stdout
        integer, intent(out) :: stat                    !! 0 or an iostat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group), allocatable :: raw(:)
        character(len=:), allocatable :: text, path
        character(len=512) :: iomsg
        integer :: u

        stat = 0
        errmsg = ''
        if (.not. opened .or. .not. par_root()) return
        rewind(unit)
        call scan_unit(unit, raw, stat, errmsg)
        if (stat /= 0) then
            errmsg = 'echo of the input: '//errmsg
            return
        end if
        text = echo_text(raw, groups)
        ! without its last newline: an advancing write ends the line
        if (len(text) > 0) text = text(1:len(text) - 1)
        if (to_stdout) write(output_unit, '(a)') text
        if (.not. to_file) return
        path = echo_file_path(prefix)
        ! under <path>.part until the run ends (driver_tables: commit_outputs, discard_outputs)
        call open_output(path, u, stat, errmsg)
        if (stat /= 0) return
        write(u, '(a)', iostat=stat, iomsg=iomsg) &
            '! effective input of '//input//' (seispulse); re-run: seispulse '//path &
            //new_line('a')//text
        if (stat == 0) then
            close(u, iostat=stat, iomsg=iomsg)
        else
            close(u)
        end if
        if (stat /= 0) errmsg = path//': cannot write the echo of the input: '//trim(iomsg)
    end subroutine echo_finish

    !> The filtered namelist text of the raw echo groups: the groups of the input, each
    !> once (items of a group echoed twice are merged, the first value of a key kept), with
    !> the keys the input gave, each with its values as the analysis echoed them, or as
    !> the input wrote them when the analysis does not echo that key.
    function echo_text(raw, groups) result(text)
        type(nml_group), intent(in) :: raw(:), groups(:)
        character(len=:), allocatable :: text
        character(len=:), allocatable :: key, gname
        type(text_buffer) :: buf
        type(string_t), allocatable :: values(:)
        type(string_t), allocatable :: done(:)
        integer :: i, i2, j, k, ig, n, eq, col
        allocate(values(0))
        do i = 1, size(raw)
            gname = lower(raw(i)%name)
            ig = find_group(groups, gname)
            if (ig == 0 .or. find_group(raw(1:i - 1), raw(i)%name) > 0) cycle
            call append(buf, '&'//gname//new_line('a'))
            allocate(done(0))
            do i2 = i, size(raw)
                if (raw(i2)%name /= raw(i)%name) cycle
                do j = 1, size(raw(i2)%items)
                    key = lower(raw(i2)%items(j)%key)
                    if (.not. given(groups(ig), key)) cycle
                    if (any([(done(k)%s == key, k = 1, size(done))])) cycle
                    done = [done, string_t(key)]
                    eq = index(raw(i2)%items(j)%text, '=')
                    call clean_values(raw(i2)%items(j)%text(eq + 1:), .true., values, n)
                    call append(buf, '    '//key//' = '//values(1)%s)
                    col = 7 + len(key) + len(values(1)%s)
                    do k = 2, n
                        if (col + 2 + len(values(k)%s) > line_len) then
                            call append(buf, ','//new_line('a')//repeat(' ', 7 + len(key)) &
                                       //values(k)%s)
                            col = 7 + len(key) + len(values(k)%s)
                        else
                            call append(buf, ', '//values(k)%s)
                            col = col + 2 + len(values(k)%s)
                        end if
                    end do
                    call append(buf, new_line('a'))
                end do
            end do
            ! keys the analysis does not echo (a range the echo gives as a list, say): as
            ! the input wrote them
            do j = 1, size(groups(ig)%items)
                key = groups(ig)%items(j)%key
                if (any([(done(k)%s == key, k = 1, size(done))])) cycle
                call append(buf, '    '//trim(adjustl(groups(ig)%items(j)%text))//new_line('a'))
            end do
            deallocate(done)
            call append(buf, '/'//new_line('a'))
        end do
        text = contents(buf)
    end function echo_text

    !> The values of one item ("v1, n*v2, ..." as gfortran writes them) as namelist input
    !> text: strings trimmed and quoted with apostrophes, reals shortest, logicals
    !> .true./.false.; trailing unset values (NaN, blank) dropped; n = 0 (drop the key)
    !> when all are unset and `keep` is false.
    subroutine clean_values(text, keep, values, n)
        character(len=*), intent(in) :: text
        logical, intent(in) :: keep
        type(string_t), allocatable, intent(out) :: values(:)
        integer, intent(out) :: n
        character(len=:), allocatable :: v
        integer, allocatable :: a(:), b(:)
        logical, allocatable :: unset(:)
        integer :: i, nt, star, reps
        call split_values(text, a, b)
        nt = size(a)
        allocate(values(nt), unset(nt))
        do i = 1, nt
            v = text(a(i):b(i))
            star = 0
            reps = 0
            if (verify(v(1:1), '0123456789') == 0) star = index(v, '*')
            if (star > 1) then
                if (verify(v(1:star - 1), '0123456789') /= 0) star = 0
            end if
            if (star > 1) then
                read(v(1:star - 1), *) reps
                v = v(star + 1:)
            end if
            call clean_value(v, unset(i))
            if (star > 1) then
                values(i)%s = int_str(reps)//'*'//v
            else
                values(i)%s = v
            end if
        end do
        n = nt
        do while (n > 0)
            if (.not. unset(n)) exit
            n = n - 1
        end do
        if (n == 0 .and. keep) n = nt
    end subroutine clean_values

    !> One value as input text, and whether it means "not set" (NaN, a blank string).
    subroutine clean_value(v, unset)
        character(len=:), allocatable, intent(inout) :: v
        logical, intent(out) :: unset
        real(dp) :: x
        integer :: ios
        unset = .false.
        if (len(v) == 0) then
            unset = .true.
            return
        end if
        select case (v(1:1))
        case ('"', '''')
            v = quoted(unquoted(v))
            unset = v == ''''''
        case ('T', 't')
            v = '.true.'
        case ('F', 'f')
            v = '.false.'
        case default
            if (scan(v, '.EeNnIi') > 0) then
                read(v, *, iostat=ios) x
                if (ios == 0) then
                    unset = ieee_is_nan(x)
                    if (unset) then
                        v = 'nan'
                    else
                        v = shortest_str(x)
                    end if
                end if
            end if
        end select
    end subroutine clean_value

    !> Split "a, b c ,d" at commas and blanks outside quotes (gfortran's namelist output):
    !> token i is text(a(i):b(i)).
    subroutine split_values(text, a, b)
        character(len=*), intent(in) :: text
        integer, allocatable, intent(out) :: a(:), b(:)
        integer :: pos, i1, i2
        allocate(a(0), b(0))
        pos = 1
        do
            call next_value(text, pos, i1, i2)
            if (i1 == 0) exit
            a = [a, i1]
            b = [b, i2]
        end do
    end subroutine split_values

    !> The text of a quoted string (either quote; doubled quotes undone), trimmed.
    pure function unquoted(v) result(s)
        character(len=*), intent(in) :: v
        character(len=:), allocatable :: s
        character :: q
        integer :: i
        q = v(1:1)
        s = ''
        i = 2
        do while (i <= len(v))
            if (v(i:i) == q) then
                if (i < len(v)) then
                    if (v(i + 1:i + 1) == q) then
                        s = s//q
                        i = i + 2
                        cycle
                    end if
                end if
                exit
            end if
            s = s//v(i:i)
            i = i + 1
        end do
        s = trim(s)
    end function unquoted

    !> 'text' with embedded apostrophes doubled.
    pure function quoted(s) result(q)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: q
        integer :: i
        q = ''''
        do i = 1, len(s)
            if (s(i:i) == '''') then
                q = q//''''''
            else
                q = q//s(i:i)
            end if
        end do
        q = q//''''
    end function quoted

    pure logical function starts_with(s, head)
        character(len=*), intent(in) :: s, head
        starts_with = .false.
        if (len(s) >= len(head)) starts_with = s(1:len(head)) == head
    end function starts_with

    !> Whether a path has a ".." component.
    pure logical function has_dotdot(p)
        character(len=*), intent(in) :: p
        has_dotdot = p == '..' .or. starts_with(p, '../') .or. index(p, '/../') > 0
        if (len(p) >= 3) has_dotdot = has_dotdot .or. p(len(p) - 2:) == '/..'
    end function has_dotdot

end module driver_echo
