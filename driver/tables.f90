!> Output tables: each table is written twice, as an aligned text table for reading
!> (numbers with &run digits significant digits, integers as integers, categories as
!> names; a one-row summary as name / value / unit lines) and as CSV (numbers with
!> &run csv_digits digits, 0: the shortest text that reads back to the same double).
!> Every file is written under a temporary name (<file>.part) and renamed when the run
!> ends without an input error (commit_outputs); on an input error (discard_outputs) the
!> temporary files and the files an earlier run wrote under the same prefix are removed.
!> table_path is the one place that builds an output file name.
!> A table is written row by row (table_t: table_open, table_comment, table_row,
!> table_close), so that a batch over thousands of records never holds its tables: the
!> CSV lines go out at once and the .txt, whose columns are aligned over all rows, is
!> assembled at the end from scratch files. write_tables writes a table held in memory
!> through the same routines.
!> Only the root of an MPI job writes: on another rank (driver_parallel) a table writes
!> nothing, open_output opens /dev/null, and nothing is renamed or deleted.
module driver_tables
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_associated
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
    use seispulse, only: dp, int_str, g_str, format_reals, NUM_LEN
    use driver_run_group, only: run_digits, run_csv_digits
    use driver_input, only: output_located
    use driver_parallel, only: par_root
    use driver_namelist_scan, only: text_buffer, append
    implicit none
    private

    public :: write_tables, delete_files, say_written, stack
    public :: table_t, table_open, table_comment, table_row, table_close, table_drop
    public :: write_table_pair, category_kind, table_path, commit_outputs, discard_outputs
    public :: open_output, status_names
    public :: make_parent_dir, remove_file

    !> The names of a row status column: 0 ok, 1 failed (category_kind(status_names)).
    character(len=6), parameter :: status_names(0:1) = [character(len=6) :: 'ok', 'failed']

    !> Column kinds (from the `kinds` argument of write_tables).
    integer, parameter :: KIND_REAL = 0, KIND_INT = 1, KIND_CAT = 2

    !> A path (a list of paths of different lengths).
    type :: path_t
        character(len=:), allocatable :: s
    end type path_t

    !> A table written row by row (table_open, then table_comment and table_row, then
    !> table_close; write_tables does all of it for a table held in memory). The CSV rows
    !> are written as they come; the .txt needs the width of every column before its
    !> first row, so its header lines and its cells wait in two scratch files until
    !> table_close: memory does not grow with the rows. The first error is kept (stat,
    !> errmsg; both files are dropped) and later calls do nothing.
    type :: table_t
        character(len=512) :: files(2) = ''       !! final paths: txt, csv
        integer :: stat = 0                       !! the first error (0: none)
        character(len=:), allocatable :: errmsg   !! its message
        logical :: writing = .false.              !! files open and no error (root only)
        logical :: created = .false.              !! its files are outputs of this run
        logical :: summary = .false.              !! one row as name/value/unit lines
        integer :: ut = -1, uc = -1               !! the .txt and the .csv (<path>.part)
        integer :: ucom = -1, ucell = -1          !! scratch: header lines, .txt cells
        integer :: ncol = 0, ndat = 0, j0 = 1     !! columns, numeric ones, first numeric
        integer :: nrow = 0, ncom = 0             !! rows and header lines so far
        integer :: digits = 0, csv_digits = 0     !! &run digits, csv_digits
        type(path_t), allocatable :: names(:), units(:)
        integer, allocatable :: kind_of(:), width(:), ncat(:)
        type(path_t), allocatable :: cats(:, :)   !! names of the category columns' codes
        type(text_buffer) :: csv_line, row_cells  !! a row being built: CSV line, .txt cells
        character(len=:), allocatable :: line, cells  !! a .txt line; a row's cells read back
        character(len=512) :: iomsg = ''
    end type table_t

    !> Final paths of the files written under <path>.part in this run, not yet renamed.
    type(path_t), allocatable :: pending(:)
    integer :: npending = 0

    interface
        ! C rename() (stdio): 0 on success.
        integer(c_int) function c_rename(old, new) bind(c, name='rename')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: old(*), new(*)
        end function c_rename
        ! POSIX unlink(): a file only (never a directory)
        integer(c_int) function c_unlink(path) bind(c, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
        end function c_unlink
        ! POSIX realpath(): the canonical absolute path into `resolved` (PATH_MAX bytes);
        ! a null pointer when the file does not exist.
        type(c_ptr) function c_realpath(path, resolved) bind(c, name='realpath')
            import :: c_ptr, c_char
            character(kind=c_char), intent(in) :: path(*)
            character(kind=c_char), intent(out) :: resolved(*)
        end function c_realpath
    end interface

contains

    !> The path of table `table` of the run with output prefix `prefix`:
    !> <dir>/<base>_<table>.<ext>, where a `_`-word suffix of <base> equal to a `_`-word
    !> prefix of <table> is written once (the longest such overlap): 'out/rocking_map' +
    !> 'rocking_map' -> out/rocking_map.<ext>; 'out/walls' + 'walls_pressure' ->
    !> out/walls_pressure.<ext>; 'out/example' + 'pulse' -> out/example_pulse.<ext>. An
    !> empty <base> ('out/') gives out/<table>.<ext>.
    pure function table_path(prefix, table, ext) result(path)
        character(len=*), intent(in) :: prefix    !! output prefix (may contain a directory)
        character(len=*), intent(in) :: table     !! table name, e.g. 'rocking_map'
        character(len=*), intent(in) :: ext       !! extension without the dot, e.g. 'txt'
        character(len=:), allocatable :: path
        character(len=:), allocatable :: dir, base, t
        integer :: k, nb, nt, over
        k = index(trim(prefix), '/', back=.true.)
        dir = prefix(1:k)
        base = trim(prefix(k + 1:))
        t = trim(table)
        nb = len(base)
        nt = len(t)
        ! the longest overlap: base ends with t(1:over), at a word start in base, and
        ! t(1:over) is whole words of t
        over = 0
        do k = min(nb, nt), 1, -1
            if (base(nb - k + 1:) /= t(1:k)) cycle
            if (k < nb) then
                if (base(nb - k:nb - k) /= '_') cycle
            end if
            if (k < nt) then
                if (t(k + 1:k + 1) /= '_') cycle
            end if
            over = k
            exit
        end do
        if (nb == 0) then
            path = dir//t
        else if (over == nt) then
            path = dir//base
        else if (over > 0) then
            path = dir//base//t(over + 1:)
        else
            path = dir//base//'_'//t
        end if
        path = path//'.'//trim(ext)
    end function table_path

    !> The kind of a category column for write_tables: 'cat:name0|name1|...' (code k >= 0
    !> is names(k); -1 is written `undecided`, NaN `nan`).
    pure function category_kind(names) result(kind)
        character(len=*), intent(in) :: names(0:)   !! the name of each code
        character(len=:), allocatable :: kind
        integer :: k
        kind = 'cat:'
        do k = 0, ubound(names, 1)
            kind = kind//trim(names(k))
            if (k < ubound(names, 1)) kind = kind//'|'
        end do
    end function category_kind

    !> Open <path>.part for writing (the directory is created) and register it: it is
    !> renamed to `path` by commit_outputs, deleted by discard_outputs. stat /= 0 with
    !> errmsg if it cannot be created or `path` is already an output of this run.
    !> On a rank other than the root of an MPI job: /dev/null, not registered.
    subroutine open_output(path, unit, stat, errmsg)
        character(len=*), intent(in) :: path            !! the final path
        integer, intent(out) :: unit
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: iomsg
        type(path_t), allocatable :: grown(:)
        integer :: i
        errmsg = ''
        unit = -1
        if (.not. par_root()) then
            open(newunit=unit, file='/dev/null', status='old', action='write', iostat=stat, &
                 iomsg=iomsg)
            if (stat /= 0) errmsg = 'cannot open /dev/null: '//trim(iomsg)
            return
        end if
        do i = 1, npending
            if (pending(i)%s == path) then
                stat = 1
                errmsg = path//': two outputs of this run have that name (choose another ' &
                         //'output prefix)'
                return
            end if
        end do
        call make_parent_dir(path)
        open(newunit=unit, file=path//'.part', status='replace', action='write', &
             iostat=stat, iomsg=iomsg)
        if (stat /= 0) then
            errmsg = 'cannot create '//path//'.part: '//trim(iomsg)
            unit = -1
            return
        end if
        if (.not. allocated(pending)) allocate(pending(16))
        if (npending == size(pending)) then
            allocate(grown(2 * npending))
            grown(1:npending) = pending
            call move_alloc(grown, pending)
        end if
        npending = npending + 1
        pending(npending)%s = path
    end subroutine open_output

    !> Rename every <path>.part of this run to <path> (the end of a run without an input
    !> error). stat /= 0 with errmsg naming the first file that could not be renamed (the
    !> others are still renamed, and all stay registered for discard_outputs).
    subroutine commit_outputs(stat, errmsg)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: i
        stat = 0
        errmsg = ''
        if (.not. par_root()) return
        do i = 1, npending
            if (c_rename(pending(i)%s//'.part'//c_null_char, &
                         pending(i)%s//c_null_char) /= 0) then
                if (stat == 0) errmsg = 'cannot rename '//pending(i)%s//'.part to ' &
                                        //pending(i)%s
                stat = 1
            end if
        end do
        if (stat == 0) npending = 0
    end subroutine commit_outputs

    !> After an input error: delete every <path>.part of this run, and the files an
    !> earlier run may have written under `prefix` (the .txt and .csv of each of
    !> `tables`, and the echo file, table 'input', .nml), so no stale result remains.
    !> The file `keep` (the input being read, e.g. an edited echo file) is never deleted,
    !> whatever name it is reached by (canonical paths are compared).
    subroutine discard_outputs(prefix, tables, keep)
        character(len=*), intent(in) :: prefix      !! output prefix ('' : none known)
        character(len=*), intent(in) :: tables(:)   !! table names (of every analysis)
        character(len=*), intent(in), optional :: keep  !! a path never to delete
        character(len=:), allocatable :: kept
        integer :: i
        if (.not. par_root()) return
        do i = 1, npending
            call remove_file(pending(i)%s//'.part')
        end do
        npending = 0
        if (len_trim(prefix) == 0) return
        kept = ''
        if (present(keep)) kept = canonical_path(keep)
        do i = 1, size(tables)
            call remove_stale(table_path(prefix, tables(i), 'txt'))
            call remove_stale(table_path(prefix, tables(i), 'csv'))
        end do
        call remove_stale(table_path(prefix, 'input', 'nml'))
    contains
        subroutine remove_stale(file)
            character(len=*), intent(in) :: file
            character(len=:), allocatable :: canon
            canon = canonical_path(file)
            if (len(canon) == 0) return   ! no such file
            if (canon == kept) return
            call remove_file(file)
        end subroutine remove_stale
    end subroutine discard_outputs

    !> The canonical absolute path of an existing file (symbolic links, '.' and '..'
    !> resolved); '' when it does not exist or cannot be resolved.
    function canonical_path(path) result(canon)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: canon
        character(kind=c_char, len=4097) :: buf
        integer :: k
        buf = ''
        if (.not. c_associated(c_realpath(trim(path)//c_null_char, buf))) then
            canon = ''
            return
        end if
        k = index(buf, c_null_char)
        if (k == 0) k = len(buf) + 1
        canon = buf(1:k - 1)
    end function canonical_path

    !> Delete a file if it exists (no error otherwise; a directory stays).
    subroutine remove_file(path)
        character(len=*), intent(in) :: path
        integer(c_int) :: rc
        rc = c_unlink(path//c_null_char)
    end subroutine remove_file

    !> Forget a registered output and delete its .part (and the final file, if any).
    subroutine drop_output(path)
        character(len=*), intent(in) :: path
        integer :: i, j
        if (.not. par_root()) return
        call remove_file(path//'.part')
        call remove_file(path)
        j = 0
        do i = 1, npending
            if (pending(i)%s == path) cycle
            j = j + 1
            if (j < i) pending(j)%s = pending(i)%s
        end do
        npending = j
    end subroutine drop_output

    !> Start table `name` of the run (see write_tables for the layout, `kinds` and
    !> `summary`; `labelled`: the first column is text, given to table_row as `label`):
    !> its .txt and .csv are created as <path>.part (open_output) and the CSV header is
    !> written. Then table_comment and table_row in any order, then table_close; after a
    !> failure elsewhere, table_drop. Nothing is written on a rank other than the root of
    !> an MPI job (t%files still names the files). stat /= 0 with errmsg: nothing is left.
    subroutine table_open(t, prefix, name, names, units, stat, errmsg, kinds, labelled, &
                          summary)
        type(table_t), intent(out) :: t
        character(len=*), intent(in) :: prefix          !! output prefix (may contain a directory)
        character(len=*), intent(in) :: name            !! table name, e.g. 'pulse'
        character(len=*), intent(in) :: names(:)        !! column names
        character(len=*), intent(in) :: units(:)        !! column units
        integer, intent(out) :: stat                    !! 0 or an iostat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=*), intent(in), optional :: kinds(:)   !! column kinds
        logical, intent(in), optional :: labelled       !! the first column is text
        logical, intent(in), optional :: summary        !! one row as name/value/unit lines
        character(len=:), allocatable :: head
        integer :: j

        t%ncol = size(names)
        t%j0 = 1
        if (present(labelled)) then
            if (labelled) t%j0 = 2
        end if
        t%ndat = t%ncol - t%j0 + 1
        t%digits = run_digits()
        t%csv_digits = run_csv_digits()
        if (present(summary)) t%summary = summary
        t%errmsg = ''
        t%files(1) = table_path(prefix, name, 'txt')
        t%files(2) = table_path(prefix, name, 'csv')
        stat = 0
        errmsg = ''
        if (.not. par_root()) return        ! the root of an MPI job writes them

        ! the names and units, the kind of each numeric column, the names of a category
        ! column, and the width of each text column: at least its name and (unit)
        allocate(t%names(t%ncol), t%units(t%ncol), t%width(t%ncol))
        do j = 1, t%ncol
            t%names(j)%s = trim(names(j))
            t%units(j)%s = trim(units(j))
            t%width(j) = max(len_trim(names(j)), len_trim(units(j)) + 2)
        end do
        allocate(t%kind_of(t%ndat), t%ncat(t%ndat), t%cats(0:63, t%ndat))
        t%kind_of = KIND_REAL
        t%ncat = 0
        if (present(kinds)) then
            do j = 1, t%ndat
                if (j + t%j0 - 1 > size(kinds)) exit
                call parse_kind(kinds(j + t%j0 - 1), t%kind_of(j), t%cats(:, j), t%ncat(j))
            end do
        end if

        call open_output(trim(t%files(1)), t%ut, stat, errmsg)
        if (stat /= 0) return
        t%created = .true.
        call open_output(trim(t%files(2)), t%uc, stat, errmsg)
        if (stat /= 0) then
            call table_fail(t, '')
            return
        end if
        t%writing = .true.
        allocate(character(len=256) :: t%csv_line%s, t%row_cells%s)
        ! the .txt waits for the widths: its header lines and cells go to two scratch
        ! files (unformatted stream: lengths, then bytes) next to it, on the disk that
        ! takes the tables (not a /tmp that may live in memory), unlinked at once
        call open_scratch(trim(t%files(1))//'.part.lines', t%ucom)
        if (t%stat == 0) call open_scratch(trim(t%files(1))//'.part.cells', t%ucell)
        if (t%stat /= 0) then
            call table_fail(t, 'cannot create a scratch file next to '//trim(t%files(1)))
        else
            ! CSV: the header "name (unit)"
            head = t%names(1)%s//' ('//t%units(1)%s//')'
            do j = 2, t%ncol
                head = head//','//t%names(j)%s//' ('//t%units(j)%s//')'
            end do
            write(t%uc, '(a)', iostat=t%stat, iomsg=t%iomsg) head
            if (t%stat /= 0) call table_write_failed(t)
        end if
        stat = t%stat
        errmsg = t%errmsg

    contains

        !> Open `path` for reading and writing and remove its name (the open file lives
        !> until it is closed; a killed run leaves nothing).
        subroutine open_scratch(path, unit)
            character(len=*), intent(in) :: path
            integer, intent(out) :: unit
            open(newunit=unit, file=path, status='replace', access='stream', &
                 form='unformatted', action='readwrite', iostat=t%stat, iomsg=t%iomsg)
            if (t%stat /= 0) then
                unit = -1
            else if (c_unlink(path//c_null_char) /= 0) then
                t%stat = 1
                t%iomsg = 'cannot remove its name'
            end if
        end subroutine open_scratch

    end subroutine table_open

    !> A header line of the .txt (written with '# ' before it; trailing blanks dropped).
    subroutine table_comment(t, line)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: line
        if (.not. t%writing) return
        write(t%ucom, iostat=t%stat, iomsg=t%iomsg) len_trim(line), trim(line)
        if (t%stat /= 0) call table_write_failed(t)
        t%ncom = t%ncom + 1
    end subroutine table_comment

    !> The next row: its numeric columns (t%ndat values) and, in a labelled table, the text
    !> of its first column. The CSV line is written now; the .txt cells wait.
    subroutine table_row(t, values, label)
        type(table_t), intent(inout) :: t
        real(dp), intent(in) :: values(:)               !! the numeric columns
        character(len=*), intent(in), optional :: label !! the first column's text
        ! each number is converted once, for the CSV cell and the .txt cell
        character(len=NUM_LEN) :: cells(size(values)), ctext(size(values))
        integer :: lens(t%ncol)
        character(len=:), allocatable :: c
        integer :: j

        if (.not. t%writing) return
        if (size(values) /= t%ndat .or. (present(label) .neqv. t%j0 == 2)) then
            ! a caller's mistake: say so rather than write a wrong row
            t%iomsg = 'table_row: '//int_str(size(values))//' values for '// &
                      int_str(t%ndat)//' numeric columns, a label given: ' &
                      //trim(merge('yes', 'no ', present(label)))
            call table_fail(t, 'internal error in '//trim(t%files(1)))
            return
        end if
        call format_reals(values, t%digits, cells, t%csv_digits, ctext)
        associate (csv => t%csv_line, txt => t%row_cells)
            csv%n = 0
            txt%n = 0
            if (present(label)) then
                call append(csv, csv_quote(label))
                lens(1) = len_trim(label)
                call append(txt, label(1:lens(1)))
            end if
            do j = 1, t%ndat
                if (csv%n > 0) call append(csv, ',')
                select case (t%kind_of(j))
                case (KIND_INT)
                    c = trim(int_text(values(j)))
                    call append(csv, c)
                case (KIND_CAT)
                    c = cat_text(t, values(j), j)
                    call append(csv, '"'//c//'"')
                case default
                    ! a number (the common case: no allocation)
                    call append(csv, ctext(j)(1:len_trim(ctext(j))))
                    lens(j + t%j0 - 1) = len_trim(cells(j))
                    call append(txt, cells(j)(1:lens(j + t%j0 - 1)))
                    cycle
                end select
                lens(j + t%j0 - 1) = len(c)
                call append(txt, c)
            end do
            do j = 1, t%ncol
                t%width(j) = max(t%width(j), lens(j))
            end do
            write(t%uc, '(a)', iostat=t%stat, iomsg=t%iomsg) csv%s(1:csv%n)
            if (t%stat == 0) write(t%ucell, iostat=t%stat, iomsg=t%iomsg) lens, txt%s(1:txt%n)
        end associate
        if (t%stat /= 0) call table_write_failed(t)
        t%nrow = t%nrow + 1
    end subroutine table_row

    !> Write the .txt (the header lines: `lead`, then those of table_comment; the column
    !> names and units; the rows aligned) and close both files (they are renamed by
    !> commit_outputs). stat /= 0 with errmsg: the first error of this table (both files
    !> are dropped).
    subroutine table_close(t, stat, errmsg, lead)
        type(table_t), intent(inout) :: t
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=*), intent(in), optional :: lead(:)  !! first header lines (known last)
        character(len=:), allocatable :: text
        integer :: k, n

        if (t%writing) then
            ! the header lines, then the table
            if (present(lead)) then
                do k = 1, size(lead)
                    if (t%stat == 0) write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) &
                        '# '//trim(lead(k))
                end do
            end if
            do k = 1, t%ncom
                if (t%stat /= 0) exit
                if (k == 1) then
                    read(t%ucom, pos=1, iostat=t%stat, iomsg=t%iomsg) n
                else
                    read(t%ucom, iostat=t%stat, iomsg=t%iomsg) n
                end if
                if (t%stat /= 0) exit
                if (allocated(text)) deallocate(text)
                allocate(character(len=n) :: text)
                read(t%ucom, iostat=t%stat, iomsg=t%iomsg) text
                if (t%stat == 0) write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) '# '//text
                if (t%stat /= 0) exit
            end do
            if (t%stat == 0) then
                if (t%summary .and. t%nrow == 1) then
                    call write_summary(t)
                else
                    call write_text_rows(t)
                end if
            end if
            if (t%stat /= 0) then
                call table_write_failed(t)
            else
                close(t%ucom, iostat=k)
                close(t%ucell, iostat=k)
                close(t%ut, iostat=t%stat, iomsg=t%iomsg)
                t%ut = -1
                if (t%stat == 0) close(t%uc, iostat=t%stat, iomsg=t%iomsg)
                t%uc = -1
                if (t%stat /= 0) call table_fail(t, 'cannot close the tables')
            end if
            t%writing = .false.
        end if
        stat = t%stat
        errmsg = ''
        if (allocated(t%errmsg)) errmsg = t%errmsg
    end subroutine table_close

    !> Give up a table (another part of the run failed): its files, being written or
    !> closed already, are dropped (no longer outputs of the run). A table never opened:
    !> nothing.
    subroutine table_drop(t)
        type(table_t), intent(inout) :: t
        if (t%created) call table_fail(t, '')
    end subroutine table_drop

    !> The row cells from the scratch file, each column right-aligned to its width (the
    !> label column left-adjusted) after a blank, under the header lines (names, then
    !> (units)) that start with '#' in place of the first blank.
    subroutine write_text_rows(t)
        type(table_t), intent(inout) :: t
        integer :: lens(t%ncol)
        integer :: i, k, pos, p
        character(len=:), allocatable :: head
        if (allocated(t%line)) deallocate(t%line)
        allocate(character(len=sum(t%width) + t%ncol) :: t%line)
        ! the header lines
        pos = 0
        do k = 1, t%ncol
            call put_cell(t%names(k)%s, k)
        end do
        t%line(1:1) = '#'
        write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) t%line(1:pos)
        pos = 0
        do k = 1, t%ncol
            head = '('//t%units(k)%s//')'
            call put_cell(head, k)
        end do
        t%line(1:1) = '#'
        if (t%stat == 0) write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) t%line(1:pos)
        ! the rows
        do i = 1, t%nrow
            if (t%stat /= 0) return
            call read_cells(t, i, lens)
            if (t%stat /= 0) return
            pos = 0
            p = 0
            do k = 1, t%ncol
                call put_cell(t%cells(p + 1:p + lens(k)), k)
                p = p + lens(k)
            end do
            write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) t%line(1:pos)
        end do
    contains
        !> Append ' ' and c in the width of column k (left-adjusted in a label column).
        subroutine put_cell(c, k)
            character(len=*), intent(in) :: c
            integer, intent(in) :: k
            integer :: w, n
            w = t%width(k)
            n = len(c)
            t%line(pos + 1:pos + 1 + w) = ' '
            if (k < t%j0) then
                t%line(pos + 2:pos + 1 + n) = c
            else
                t%line(pos + 2 + w - n:pos + 1 + w) = c
            end if
            pos = pos + 1 + w
        end subroutine put_cell
    end subroutine write_text_rows

    !> One `name  value  unit` line per column (the one row of a summary).
    subroutine write_summary(t)
        type(table_t), intent(inout) :: t
        integer :: lens(t%ncol)
        integer :: wn, wv, k, p
        call read_cells(t, 1, lens)
        if (t%stat /= 0) return
        wn = 0
        do k = 1, t%ncol
            wn = max(wn, len(t%names(k)%s))
        end do
        wv = maxval(lens)
        p = 0
        do k = 1, t%ncol
            if (t%stat /= 0) return
            write(t%ut, '(a)', iostat=t%stat, iomsg=t%iomsg) pad(t%names(k)%s, wn)//'  ' &
                //repeat(' ', wv - lens(k))//t%cells(p + 1:p + lens(k))//'  '//t%units(k)%s
            p = p + lens(k)
        end do
    end subroutine write_summary

    !> The cells of row i (rows are read in order) into t%cells, their lengths into lens.
    subroutine read_cells(t, i, lens)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: i
        integer, intent(out) :: lens(:)
        integer :: n
        if (i == 1) then
            read(t%ucell, pos=1, iostat=t%stat, iomsg=t%iomsg) lens
        else
            read(t%ucell, iostat=t%stat, iomsg=t%iomsg) lens
        end if
        if (t%stat /= 0) return
        n = sum(lens)
        if (.not. allocated(t%cells)) allocate(character(len=max(256, n)) :: t%cells)
        if (len(t%cells) < n) then
            deallocate(t%cells)
            allocate(character(len=2 * n) :: t%cells)
        end if
        read(t%ucell, iostat=t%stat, iomsg=t%iomsg) t%cells(1:n)
    end subroutine read_cells

    !> A category code as its name ('undecided' for -1, 'nan' for NaN) of numeric column j.
    function cat_text(t, x, j) result(c)
        type(table_t), intent(in) :: t
        real(dp), intent(in) :: x
        integer, intent(in) :: j
        character(len=:), allocatable :: c
        integer :: k
        if (ieee_is_nan(x)) then
            c = 'nan'
            return
        end if
        k = -2
        if (abs(x) < 1.0e9_dp) k = nint(x)
        if (abs(x - real(k, dp)) > 0.0_dp) k = -2   ! not a code
        if (k >= 0 .and. k < t%ncat(j)) then
            c = t%cats(k, j)%s
        else if (k == -1) then
            c = 'undecided'
        else
            c = g_str(x, 17)
        end if
    end function cat_text

    !> A write failed: the message names the files and the system's reason.
    subroutine table_write_failed(t)
        type(table_t), intent(inout) :: t
        call table_fail(t, 'cannot write '//trim(t%files(1))//' / '//trim(t%files(2)))
    end subroutine table_write_failed

    !> Close and drop both files; keep the first error (`what`: its text, '' to keep the
    !> one set already).
    subroutine table_fail(t, what)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: what
        integer :: ios
        if (len(what) > 0 .and. len(t%errmsg) == 0) t%errmsg = what//': '//trim(t%iomsg)
        if (t%ut /= -1) close(t%ut, iostat=ios)
        if (t%uc /= -1) close(t%uc, iostat=ios)
        if (t%ucom /= -1) close(t%ucom, iostat=ios)
        if (t%ucell /= -1) close(t%ucell, iostat=ios)
        t%ut = -1
        t%uc = -1
        t%ucom = -1
        t%ucell = -1
        call drop_output(trim(t%files(1)))
        call drop_output(trim(t%files(2)))
        if (t%stat == 0) t%stat = 1
        t%writing = .false.
        t%created = .false.
    end subroutine table_fail

    !> Write table `name` of the run: table_path(prefix, name, 'txt') and (..., 'csv')
    !> (as <path>.part until commit_outputs).
    !>
    !> With `labels` (one text per row) the first column is text: names(1) and units(1)
    !> describe it and `data` holds the other columns. In the .txt it is left-adjusted
    !> and padded to the longest label (at least the width of its name and unit); in the
    !> .csv it is the first field, double-quoted (embedded quotes doubled).
    !> `kinds` (one per entry of names; the label column's entry is ignored): '' or
    !> 'real' (a number), 'int' (an integer, written as one), 'cat:name0|name1|...' (a
    !> code k >= 0 written as its name, -1 as `undecided`, NaN as `nan`; double-quoted in
    !> the .csv). With `summary` and one row, the .txt has one `name  value  unit` line
    !> per column instead of a header and a row (the .csv is the same).
    !> On a rank other than the root of an MPI job: only `files` (nothing is written).
    !> A table built row by row (a batch) uses table_open ... table_close directly.
    subroutine write_tables(prefix, name, comments, names, units, data, files, stat, errmsg, &
                            labels, kinds, summary)
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
        character(len=*), intent(in), optional :: kinds(:)   !! column kinds (see above)
        logical, intent(in), optional :: summary        !! one row as name/value/unit lines
        type(table_t) :: t
        integer :: i
        ! an absent kinds/summary is passed on as absent
        call table_open(t, prefix, name, names, units, stat, errmsg, kinds=kinds, &
                        labelled=present(labels), summary=summary)
        files = t%files
        if (stat /= 0) return
        do i = 1, size(comments)
            call table_comment(t, comments(i))
        end do
        do i = 1, size(data, 1)
            if (present(labels)) then
                call table_row(t, data(i, :), labels(i))
            else
                call table_row(t, data(i, :))
            end if
        end do
        call table_close(t, stat, errmsg)
    end subroutine write_tables

    !> An integer-valued number as an integer ("3", "-1"); "nan"; else g_str's 17 digits.
    pure function int_text(x) result(c)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: c
        character(len=24) :: buf
        if (ieee_is_finite(x)) then
            if (abs(x) < 2.0_dp**62 .and. .not. abs(aint(x) - x) > 0.0_dp) then
                write(buf, '(i0)') int(x, int64)
                c = trim(buf)
                return
            end if
        end if
        c = g_str(x, 17)
    end function int_text

    !> Parse a column kind: '' or 'real', 'int', 'cat:a|b|...'.
    pure subroutine parse_kind(kind, k, names, n)
        character(len=*), intent(in) :: kind
        integer, intent(out) :: k
        type(path_t), intent(inout) :: names(0:)
        integer, intent(out) :: n
        integer :: a, b
        n = 0
        k = KIND_REAL
        if (trim(kind) == 'int') then
            k = KIND_INT
        else if (len_trim(kind) >= 4) then
            if (kind(1:4) /= 'cat:') return
            k = KIND_CAT
            a = 5
            do while (a <= len_trim(kind) + 1 .and. n <= ubound(names, 1))
                b = index(kind(a:), '|')
                if (b == 0) then
                    b = len_trim(kind) + 1
                else
                    b = a + b - 1
                end if
                names(n)%s = kind(a:b - 1)
                n = n + 1
                a = b + 1
            end do
        end if
    end subroutine parse_kind

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

    !> "<what> written to <txt> and <csv>" on standard output.
    subroutine say_written(what, files)
        character(len=*), intent(in) :: what      !! e.g. 'pulse table'
        character(len=*), intent(in) :: files(2)  !! paths written (txt, csv)
        write(output_unit, '(a)') what//' written to '//trim(files(1))//' and '//trim(files(2))
    end subroutine say_written

    !> Remove tables already written by this run (a later table of the same run failed):
    !> their temporary files are deleted and they are no longer renamed at the end.
    subroutine delete_files(files)
        character(len=*), intent(in) :: files(:)    !! final paths, as write_tables gives
        integer :: i
        do i = 1, size(files)
            call drop_output(trim(files(i)))
        end do
    end subroutine delete_files

    !> The two tables of one run, name1 and name2 (write_tables each, with their own
    !> comments, names, units, data and optional labels, kinds, summary): both or neither
    !> exist (the first is deleted when the second fails). Then `note` (if given) and
    !> "<what1> written to ...", "<what2> written to ..." on standard output. stat 0, or
    !> errmsg "<path>:<line>: &run: output: ...".
    subroutine write_table_pair(path, prefix, name1, comments1, names1, units1, data1, &
                                what1, name2, comments2, names2, units2, data2, what2, &
                                stat, errmsg, labels1, labels2, note, kinds1, kinds2, &
                                summary1, summary2)
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
        character(len=*), intent(in), optional :: kinds1(:), kinds2(:)  !! column kinds
        logical, intent(in), optional :: summary1, summary2  !! one-row summary layout
        character(len=512) :: files1(2), files2(2)
        ! an absent labels1/labels2 is passed on as absent
        call write_tables(prefix, name1, comments1, names1, units1, data1, files1, stat, &
                          errmsg, labels=labels1, kinds=kinds1, summary=summary1)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call write_tables(prefix, name2, comments2, names2, units2, data2, files2, stat, &
                          errmsg, labels=labels2, kinds=kinds2, summary=summary2)
        if (stat /= 0) then
            call delete_files(files1)
            errmsg = output_located(path)//errmsg
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
