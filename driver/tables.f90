!> Output tables: each table is written twice, as an aligned text table for reading
!> (numbers with &run digits significant digits, integers as integers, categories as
!> names; a one-row summary as name / value / unit lines) and as CSV (numbers with
!> &run csv_digits digits, 0: the shortest text that reads back to the same double).
!> Every file is written under a temporary name (<file>.part) and renamed when the run
!> ends without an input error (commit_outputs); on an input error (discard_outputs) the
!> temporary files and the files an earlier run wrote under the same prefix are removed.
!> table_path is the one place that builds an output file name.
!> Only the root of an MPI job writes: on another rank (driver_parallel) write_tables
!> writes nothing, open_output opens /dev/null, and nothing is renamed or deleted.
module driver_tables
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_associated
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
    use seispulse, only: dp, int_str, g_str, format_reals, NUM_LEN
    use driver_run_group, only: run_digits, run_csv_digits
    use driver_input, only: output_located
    use driver_parallel, only: par_root
    implicit none
    private

    public :: write_tables, delete_files, say_written, stack
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
        character(len=512) :: iomsg
        integer :: ut, uc, i, j, ncol, j0, nrow, ndat, digits, csv_digits, pos
        integer, allocatable :: kind_of(:), width(:)
        type(path_t), allocatable :: cats(:, :)
        integer, allocatable :: ncat(:)
        ! the text of each cell of the .txt (a category name longer than that is
        ! written from cat_text directly)
        character(len=NUM_LEN), allocatable :: cells(:, :)
        character(len=NUM_LEN), allocatable :: ctext(:)      ! the CSV cells of a row
        character(len=:), allocatable :: line, head, text
        logical :: as_summary

        ncol = size(names)
        nrow = size(data, 1)
        ndat = size(data, 2)
        j0 = 1          ! first numeric column in names/units
        if (present(labels)) j0 = 2
        digits = run_digits()
        csv_digits = run_csv_digits()
        as_summary = .false.
        if (present(summary)) as_summary = summary .and. nrow == 1
        errmsg = ''
        iomsg = ''
        files(1) = table_path(prefix, name, 'txt')
        files(2) = table_path(prefix, name, 'csv')
        stat = 0
        if (.not. par_root()) return        ! the root of an MPI job writes them

        ! the kind of each numeric column, and the names of a category column
        allocate(kind_of(ndat), ncat(ndat), cats(0:63, ndat))
        kind_of = KIND_REAL
        ncat = 0
        if (present(kinds)) then
            do j = 1, ndat
                if (j + j0 - 1 > size(kinds)) exit
                call parse_kind(kinds(j + j0 - 1), kind_of(j), cats(:, j), ncat(j))
            end do
        end if

        ut = -1
        uc = -1
        call open_output(trim(files(1)), ut, stat, errmsg)
        if (stat /= 0) return
        call open_output(trim(files(2)), uc, stat, errmsg)
        if (stat /= 0) then
            call fail('')
            return
        end if

        ! the width of each text column: at least its name and (unit)
        allocate(width(ncol))
        do j = 1, ncol
            width(j) = max(len_trim(names(j)), len_trim(units(j)) + 2)
        end do
        if (present(labels)) then
            do i = 1, nrow
                width(1) = max(width(1), len_trim(labels(i)))
            end do
        end if

        ! CSV: header "name (unit)", then the rows; each number is converted once, for
        ! the CSV cell and the text cell (kept for the .txt, written when the widths
        ! are known)
        head = trim(names(1))//' ('//trim(units(1))//')'
        do j = 2, ncol
            head = head//','//trim(names(j))//' ('//trim(units(j))//')'
        end do
        write(uc, '(a)', iostat=stat, iomsg=iomsg) head
        allocate(cells(nrow, ndat), ctext(ndat))
        do i = 1, nrow
            if (stat /= 0) exit
            call format_reals(data(i, :), digits, cells(i, :), csv_digits, ctext)
            pos = 0
            if (present(labels)) call put(csv_quote(labels(i)))
            do j = 1, ndat
                if (pos > 0) call put(',')
                select case (kind_of(j))
                case (KIND_INT)
                    cells(i, j) = int_text(data(i, j))
                    call put(trim(cells(i, j)))
                case (KIND_CAT)
                    head = cat_text(data(i, j), j)
                    cells(i, j) = head
                    call put('"'//head//'"')
                    width(j + j0 - 1) = max(width(j + j0 - 1), len(head))
                case default
                    call put(trim(ctext(j)))
                end select
                width(j + j0 - 1) = max(width(j + j0 - 1), len_trim(cells(i, j)))
            end do
            write(uc, '(a)', iostat=stat, iomsg=iomsg) text(1:pos)
        end do

        do i = 1, size(comments)
            if (stat /= 0) exit
            write(ut, '(a)', iostat=stat, iomsg=iomsg) '# '//trim(comments(i))
        end do
        if (stat == 0) then
            if (as_summary) then
                call write_summary(cells)
            else
                call write_text_table(cells)
            end if
        end if
        if (stat /= 0) then
            call fail('cannot write '//trim(files(1))//' / '//trim(files(2)))
            return
        end if
        close(ut, iostat=stat, iomsg=iomsg)
        if (stat == 0) close(uc, iostat=stat, iomsg=iomsg)
        if (stat /= 0) call fail('cannot close the tables')

    contains

        !> Append c to the CSV line text(1:pos).
        subroutine put(c)
            character(len=*), intent(in) :: c
            character(len=:), allocatable :: grown
            if (.not. allocated(text)) allocate(character(len=max(256, 2 * len(c))) :: text)
            if (pos + len(c) > len(text)) then
                allocate(character(len=2 * (pos + len(c))) :: grown)
                grown(1:pos) = text(1:pos)
                call move_alloc(grown, text)
            end if
            text(pos + 1:pos + len(c)) = c
            pos = pos + len(c)
        end subroutine put

        !> The text of cell (i, j) of the .txt: cells(i, j), or a category name longer
        !> than that.
        function cell_of(cells, i, j) result(c)
            character(len=*), intent(in) :: cells(:, :)
            integer, intent(in) :: i, j
            character(len=:), allocatable :: c
            if (kind_of(j) == KIND_CAT) then
                c = cat_text(data(i, j), j)
            else
                c = trim(cells(i, j))
            end if
        end function cell_of

        !> A category code as its name ('undecided' for -1, 'nan' for NaN).
        function cat_text(x, j) result(c)
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
            if (k >= 0 .and. k < ncat(j)) then
                c = cats(k, j)%s
            else if (k == -1) then
                c = 'undecided'
            else
                c = g_str(x, 17)
            end if
        end function cat_text

        !> The header lines and the rows of the .txt: columns right-aligned to their
        !> width (a text column left-adjusted), each after a blank; the header lines
        !> (names, then (units)) start with '#' in place of the first blank.
        subroutine write_text_table(cells)
            character(len=*), intent(in) :: cells(:, :)
            integer :: n
            n = sum(width) + ncol
            allocate(character(len=n) :: line)
            if (stat /= 0) return
            call header_line(names, .false.)
            if (stat /= 0) return
            call header_line(units, .true.)
            do i = 1, nrow
                if (stat /= 0) return
                pos = 0
                if (present(labels)) call put_cell(labels(i), width(1), .true.)
                do j = 1, ndat
                    call put_cell(cell_of(cells, i, j), width(j + j0 - 1), .false.)
                end do
                write(ut, '(a)', iostat=stat, iomsg=iomsg) line(1:pos)
            end do
        end subroutine write_text_table

        subroutine header_line(words, in_parens)
            character(len=*), intent(in) :: words(:)
            logical, intent(in) :: in_parens
            integer :: k
            pos = 0
            do k = 1, ncol
                if (in_parens) then
                    head = '('//trim(words(k))//')'
                else
                    head = trim(words(k))
                end if
                if (k < j0) then
                    call put_cell(head, width(k), .true.)
                else
                    call put_cell(head, width(k), .false.)
                end if
            end do
            line(1:1) = '#'
            write(ut, '(a)', iostat=stat, iomsg=iomsg) line(1:pos)
        end subroutine header_line

        !> Append ' ' and c in w characters, left-adjusted or right-aligned.
        subroutine put_cell(c, w, left_adjusted)
            character(len=*), intent(in) :: c
            integer, intent(in) :: w
            logical, intent(in) :: left_adjusted
            integer :: n
            n = len_trim(c)
            line(pos + 1:pos + 1 + w) = ' '
            if (left_adjusted) then
                line(pos + 2:pos + 1 + n) = c(1:n)
            else
                line(pos + 2 + w - n:pos + 1 + w) = c(1:n)
            end if
            pos = pos + 1 + w
        end subroutine put_cell

        !> One `name  value  unit` line per column (the one row of a summary).
        subroutine write_summary(cells)
            character(len=*), intent(in) :: cells(:, :)
            integer :: wn, wv, k
            character(len=:), allocatable :: v
            wn = 0
            wv = 0
            do k = 1, ncol
                wn = max(wn, len_trim(names(k)))
                if (k < j0) then
                    wv = max(wv, len_trim(labels(1)))
                else
                    wv = max(wv, len(cell_of(cells, 1, k - j0 + 1)))
                end if
            end do
            do k = 1, ncol
                if (stat /= 0) return
                if (k < j0) then
                    v = trim(labels(1))
                else
                    v = cell_of(cells, 1, k - j0 + 1)
                end if
                write(ut, '(a)', iostat=stat, iomsg=iomsg) pad(names(k), wn)//'  ' &
                    //repeat(' ', wv - len(v))//v//'  '//trim(units(k))
            end do
        end subroutine write_summary

        subroutine fail(what)
            character(len=*), intent(in) :: what
            if (len(what) > 0) errmsg = what//': '//trim(iomsg)
            if (ut /= -1) close(ut, iostat=i)
            if (uc /= -1) close(uc, iostat=i)
            call drop_output(trim(files(1)))
            call drop_output(trim(files(2)))
            if (stat == 0) stat = 1
        end subroutine fail

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
