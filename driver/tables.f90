!> Output tables: each table is written twice, as a fixed-width text table with a
!> header of names and units, and as CSV. Either both files are complete or neither
!> exists: on any write error both are deleted.
module driver_tables
    use, intrinsic :: iso_fortran_env, only: output_unit
    use seispulse, only: dp, int_str
    implicit none
    private

    public :: write_tables, column_len, delete_files, say_written, code_legend, stack
    public :: write_table_pair

    !> Width of a text column: a blank, then es24.16e3 (a negative number fills all 24).
    integer, parameter :: column_len = 25

contains

    !> Write <prefix>_<name>.txt and <prefix>_<name>.csv.
    !>
    !> With `labels` (one text per row) the first column is text: names(1) and units(1)
    !> describe it and `data` holds the other columns. In the .txt it is left-adjusted
    !> and padded to the longest label (at least the width of its name and unit); in the
    !> .csv it is the first field, double-quoted (embedded quotes doubled).
    subroutine write_tables(prefix, name, comments, names, units, data, files, stat, errmsg, &
                            labels)
        character(len=*), intent(in) :: prefix          !! output prefix (may contain a directory)
        character(len=*), intent(in) :: name            !! table name, e.g. 'pulse'
        character(len=*), intent(in) :: comments(:)     !! lines for the text header
        character(len=*), intent(in) :: names(:)        !! column names
        character(len=*), intent(in) :: units(:)        !! column units
        real(dp), intent(in) :: data(:, :)              !! rows x columns (numeric columns)
        character(len=*), intent(out) :: files(2)       !! paths written (txt, csv)
        integer, intent(out) :: stat                    !! 0 or an iostat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=*), intent(in), optional :: labels(:)  !! text of the first column, per row
        character(len=512) :: iomsg
        integer :: ut, uc, i, j, ncol, j0, width
        character(len=:), allocatable :: row, line, head

        ncol = size(names)
        j0 = 1          ! first numeric column in names/units
        width = 0       ! width of the text column (0: none)
        if (present(labels)) then
            j0 = 2
            width = max(len_trim(names(1)), len_trim(units(1)) + 2)
            do i = 1, size(labels)
                width = max(width, len_trim(labels(i)))
            end do
        end if
        allocate(character(len=(column_len + 1) * ncol) :: line)
        errmsg = ''
        files(1) = trim(prefix)//'_'//trim(name)//'.txt'
        files(2) = trim(prefix)//'_'//trim(name)//'.csv'
        call make_parent_dir(files(1))
        ut = -1
        uc = -1
        open(newunit=ut, file=trim(files(1)), status='replace', action='write', &
             iostat=stat, iomsg=iomsg)
        if (stat /= 0) then
            call fail('cannot create '//trim(files(1)))
            return
        end if
        open(newunit=uc, file=trim(files(2)), status='replace', action='write', &
             iostat=stat, iomsg=iomsg)
        if (stat /= 0) then
            call fail('cannot create '//trim(files(2)))
            return
        end if
        do i = 1, size(comments)
            write(ut, '(a)', iostat=stat, iomsg=iomsg) '# '//trim(comments(i))
            if (stat /= 0) exit
        end do
        ! the text column of the header lines: left-adjusted, `width` wide
        head = ''
        if (width > 0) head = pad(names(1), width)
        if (stat == 0) write(ut, '(a, *(a))', iostat=stat, iomsg=iomsg) '#'//head, &
            (adjustr(cell(names(j), column_len - 1)), j = j0, ncol)
        if (width > 0) head = pad('('//trim(units(1))//')', width)
        if (stat == 0) write(ut, '(a, *(a))', iostat=stat, iomsg=iomsg) '#'//head, &
            (adjustr(cell('('//trim(units(j))//')', column_len - 1)), j = j0, ncol)
        if (stat == 0) then
            row = trim(names(1))//' ('//trim(units(1))//')'
            do j = 2, ncol
                row = row//','//trim(names(j))//' ('//trim(units(j))//')'
            end do
            write(uc, '(a)', iostat=stat, iomsg=iomsg) row
        end if
        do i = 1, size(data, 1)
            if (stat /= 0) exit
            if (width > 0) then
                write(line, '(*(1x, es24.16e3))', iostat=stat, iomsg=iomsg) data(i, :)
                if (stat == 0) write(ut, '(a)', iostat=stat, iomsg=iomsg) ' ' &
                    //pad(labels(i), width)//trim(line)
            else
                write(ut, '(*(1x, es24.16e3))', iostat=stat, iomsg=iomsg) data(i, :)
            end if
            if (stat == 0) then
                ! CSV: the same 17 significant digits, blanks squeezed out
                write(line, '(*(es24.16e3, :, ","))', iostat=stat, iomsg=iomsg) data(i, :)
                if (stat == 0) then
                    if (width > 0) then
                        if (size(data, 2) > 0) then
                            write(uc, '(a)', iostat=stat, iomsg=iomsg) &
                                csv_quote(labels(i))//','//squeeze(line)
                        else
                            write(uc, '(a)', iostat=stat, iomsg=iomsg) csv_quote(labels(i))
                        end if
                    else
                        write(uc, '(a)', iostat=stat, iomsg=iomsg) squeeze(line)
                    end if
                end if
            end if
        end do
        if (stat /= 0) then
            call fail('cannot write '//trim(files(1))//' / '//trim(files(2)))
            return
        end if
        close(ut, iostat=stat, iomsg=iomsg)
        if (stat == 0) close(uc, iostat=stat, iomsg=iomsg)
        if (stat /= 0) call fail('cannot close the tables')

    contains

        subroutine fail(what)
            character(len=*), intent(in) :: what
            integer :: ios
            errmsg = what//': '//trim(iomsg)
            if (ut /= -1) close(ut, status='delete', iostat=ios)
            if (uc /= -1) close(uc, status='delete', iostat=ios)
            if (stat == 0) stat = 1
        end subroutine fail

    end subroutine write_tables

    !> s without blanks.
    pure function squeeze(s) result(r)
        character(len=*), intent(in) :: s
        character(len=:), allocatable :: r
        integer :: i, n
        character(len=len(s)) :: buf
        n = 0
        do i = 1, len_trim(s)
            if (s(i:i) /= ' ') then
                n = n + 1
                buf(n:n) = s(i:i)
            end if
        end do
        r = buf(1:n)
    end function squeeze

    !> text (trailing blanks dropped), then blanks up to `width` characters.
    pure function pad(text, width) result(c)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=max(width, len_trim(text))) :: c
        c = text
    end function pad

    !> "text" for CSV: trailing blanks dropped, embedded double quotes doubled.
    pure function csv_quote(text) result(q)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: q
        integer :: i
        q = '"'
        do i = 1, len_trim(text)
            if (text(i:i) == '"') then
                q = q//'""'
            else
                q = q//text(i:i)
            end if
        end do
        q = q//'"'
    end function csv_quote

    pure function cell(text, width) result(c)
        character(len=*), intent(in) :: text
        integer, intent(in) :: width
        character(len=width + 1) :: c
        c = ' '//text
    end function cell

    !> Create the directory part of `path` if there is one (mkdir -p).
    subroutine make_parent_dir(path)
        character(len=*), intent(in) :: path
        integer :: k, code
        character(len=:), allocatable :: dir, quoted
        k = index(path, '/', back=.true.)
        if (k <= 1) return
        dir = path(1:k - 1)
        ! single-quote the name for the shell, escaping embedded quotes
        quoted = ''''
        do code = 1, len(dir)
            if (dir(code:code) == '''') then
                quoted = quoted//'''\'''''
            else
                quoted = quoted//dir(code:code)
            end if
        end do
        quoted = quoted//''''
        ! a failure shows up when the table is opened, with a better message
        call execute_command_line('mkdir -p -- '//quoted//' 2>/dev/null', exitstat=code)
    end subroutine make_parent_dir

    !> "title: 0 name, 1 name, ..." of a column of codes 0, 1, ... (a header line).
    pure function code_legend(title, names) result(text)
        character(len=*), intent(in) :: title
        character(len=*), intent(in) :: names(0:)       !! the name of each code
        character(len=:), allocatable :: text
        integer :: k
        text = title//':'
        do k = 0, ubound(names, 1)
            text = text//' '//int_str(k)//' '//trim(names(k))
            if (k < ubound(names, 1)) text = text//','
        end do
    end function code_legend

    !> "<what> written to <txt> and <csv>" on standard output.
    subroutine say_written(what, files)
        character(len=*), intent(in) :: what      !! e.g. 'pulse table'
        character(len=*), intent(in) :: files(2)  !! paths written (txt, csv)
        write(output_unit, '(a)') what//' written to '//trim(files(1))//' and '//trim(files(2))
    end subroutine say_written

    !> Remove tables already written (a later table of the same run failed): no
    !> half-written output is left behind.
    subroutine delete_files(files)
        character(len=*), intent(in) :: files(:)
        integer :: i, u, ios
        do i = 1, size(files)
            open(newunit=u, file=trim(files(i)), status='old', iostat=ios)
            if (ios == 0) close(u, status='delete', iostat=ios)
        end do
    end subroutine delete_files

    !> The two tables of one run, <prefix>_<name1> and <prefix>_<name2> (write_tables each,
    !> with their own comments, names, units, data and optional labels): both or neither
    !> exist (the first is deleted when the second fails). Then `note` (if given) and
    !> "<what1> written to ...", "<what2> written to ..." on standard output. stat 0, or
    !> errmsg "<path>: &run: output: ...".
    subroutine write_table_pair(path, prefix, name1, comments1, names1, units1, data1, &
                                what1, name2, comments2, names2, units2, data2, what2, &
                                stat, errmsg, labels1, labels2, note)
        character(len=*), intent(in) :: path            !! input file (for messages)
        character(len=*), intent(in) :: prefix          !! output prefix
        character(len=*), intent(in) :: name1, name2    !! table names
        character(len=*), intent(in) :: comments1(:), comments2(:)
        character(len=*), intent(in) :: names1(:), names2(:), units1(:), units2(:)
        real(dp), intent(in) :: data1(:, :), data2(:, :)
        character(len=*), intent(in) :: what1, what2    !! e.g. 'winkler summary'
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=*), intent(in), optional :: labels1(:), labels2(:)
        character(len=*), intent(in), optional :: note  !! a line before the two
        character(len=512) :: files1(2), files2(2)
        ! an absent labels1/labels2 is passed on as absent
        call write_tables(prefix, name1, comments1, names1, units1, data1, files1, stat, &
                          errmsg, labels=labels1)
        if (stat /= 0) then
            errmsg = path//': &run: output: '//errmsg
            return
        end if
        call write_tables(prefix, name2, comments2, names2, units2, data2, files2, stat, &
                          errmsg, labels=labels2)
        if (stat /= 0) then
            call delete_files(files1)
            errmsg = path//': &run: output: '//errmsg
            return
        end if
        if (present(note)) write(output_unit, '(a)') note
        call say_written(what1, files1)
        call say_written(what2, files2)
    end subroutine write_table_pair

    !> Rows of b under the rows of a (tables built record by record).
    pure function stack(a, b) result(c)
        real(dp), intent(in) :: a(:, :), b(:, :)
        real(dp) :: c(size(a, 1) + size(b, 1), size(a, 2))
        c(1:size(a, 1), :) = a
        c(size(a, 1) + 1:, :) = b
    end function stack

end module driver_tables
