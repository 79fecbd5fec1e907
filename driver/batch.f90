!> The batch engine: an analysis whose work splits into independent units (for the
!> records analyses one unit = one record with all its rows) hands them to batch_run,
!> which computes them where driver_parallel says (OpenMP threads, MPI ranks), keeps a
!> restart journal, prints the units' stderr lines in unit order and hands every unit's
!> result, in unit order, to the analysis, which writes it into its tables at once: a
!> result is held only until the units before it are done, so memory does not grow with
!> the number of units.
!>
!> **The journal** `<output>.journal` (next to the tables; README "Batch driver",
!> "Restart") records each unit as it is finished, so that a run that is killed can be
!> resumed with `restart = .true.` in &run: the units found in the journal are not
!> computed again. It is a text file, one line per unit, each line written whole and
!> handed to the operating system (fflush: a killed run keeps it) before the next unit is
!> delivered, and forced to disk (fsync: a power loss keeps it) at most once a second:
!>
!>     seispulse-journal 2 <fingerprint: 16 hex digits> <number of units>
!>     u <unit> <n> <value 1> ... <value n> <text> <log> <checksum: 16 hex digits>
!>
!> Values are the IEEE 754 bit patterns of the doubles as 16 lowercase hex digits (exact:
!> a restored unit gives the same tables, bit for bit). <text> and <log> are `-` when
!> absent, else `=` followed by the string with `%`, blanks, control characters (new line,
!> the field separator) and DEL written as `%XX` (hex). The checksum is the 64-bit FNV-1a
!> hash of the bytes of the line before the blank that precedes it. The fingerprint is the
!> FNV-1a hash of the journal format, the seispulse version, the analysis, the bytes of the
!> input file and the key of every unit (a hash of the record file's path, its size and
!> how it is read and scaled; format 1 took the keys as they are, so its journals are
!> refused as of another format): a journal whose fingerprint differs belongs to another
!> run and is refused,
!> as is one with a damaged line (checksum, a unit out of range or twice, a malformed
!> field); an unterminated last line (the run was killed while writing it) is dropped and
!> that unit computed again. The journal is removed once the tables are committed
!> (batch_commit, from the driver's end of run), and after an error (exit status 2) unless
!> the run was a restart (batch_discard); a killed run leaves it. The journal also keeps
!> memory bounded: a restored unit, and a unit finished out of turn while the allowed bytes of
!> results wait already, is read back from its line when its turn comes.
module driver_batch
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, int64
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_ptr, c_size_t, c_null_char, &
                                           c_null_ptr, c_associated
    use seispulse, only: dp, int_str, seispulse_version
    use driver_unit_result, only: unit_result_t, add_field, get_field, unit_deliver
    use driver_parallel, only: par_run_units, par_root, par_finalize, unit_work
    use driver_run_group, only: run_restart
    use driver_tables, only: make_parent_dir, remove_file
    use driver_records, only: record_in_t, record_out_t
    implicit none
    private

    public :: batch_run, batch_commit, batch_discard, journal_path
    public :: record_keys, pack_record, unpack_record, RECORD_VALUES, RECORD_FIELDS

    !> Version of the journal format (the header's second word).
    integer, parameter :: JOURNAL_FORMAT = 2
    character(len=*), parameter :: MAGIC = 'seispulse-journal'
    !> Values and text fields pack_record puts first in a unit's result.
    integer, parameter :: RECORD_VALUES = 7, RECORD_FIELDS = 2
    !> FNV-1a 64: offset basis 0xcbf29ce484222325 and prime 2^40 + 0x1b3, in 32-bit limbs.
    integer(int64), parameter :: FNV_HI = 3421674724_int64, FNV_LO = 2216829733_int64
    integer(int64), parameter :: MASK32 = 4294967295_int64
    character(len=16), parameter :: HEX = '0123456789abcdef'
    !> Bytes of the input file hashed per read.
    integer, parameter :: CHUNK = 65536
    !> Separator of the parts of a record's key.
    character(len=1), parameter :: KEY_SEP = '|'

    !> A 64-bit FNV-1a hash in two 32-bit limbs (no integer overflow anywhere).
    type :: fnv_t
        integer(int64) :: hi = FNV_HI
        integer(int64) :: lo = FNV_LO
    end type fnv_t

    interface
        ! C stdio and POSIX: the journal is written with C streams so that each line can
        ! be forced to disk (fflush, then fsync of the stream's file descriptor).
        type(c_ptr) function c_fopen(path, mode) bind(c, name='fopen')
            import :: c_ptr, c_char
            character(kind=c_char), intent(in) :: path(*), mode(*)
        end function c_fopen
        integer(c_size_t) function c_fwrite(buf, size, count, stream) bind(c, name='fwrite')
            import :: c_size_t, c_char, c_ptr
            character(kind=c_char), intent(in) :: buf(*)
            integer(c_size_t), value, intent(in) :: size, count
            type(c_ptr), value, intent(in) :: stream
        end function c_fwrite
        integer(c_int) function c_fflush(stream) bind(c, name='fflush')
            import :: c_int, c_ptr
            type(c_ptr), value, intent(in) :: stream
        end function c_fflush
        integer(c_int) function c_fileno(stream) bind(c, name='fileno')
            import :: c_int, c_ptr
            type(c_ptr), value, intent(in) :: stream
        end function c_fileno
        integer(c_int) function c_fsync(fd) bind(c, name='fsync')
            import :: c_int
            integer(c_int), value, intent(in) :: fd
        end function c_fsync
        integer(c_int) function c_fclose(stream) bind(c, name='fclose')
            import :: c_int, c_ptr
            type(c_ptr), value, intent(in) :: stream
        end function c_fclose
        integer(c_int) function c_rename(old, new) bind(c, name='rename')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: old(*), new(*)
        end function c_rename
        ! C exit(): a worker rank ends without gfortran's STOP line
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value, intent(in) :: status
        end subroutine c_exit
    end interface

    ! --- the state of the batch being delivered (written on the root by `deliver` only,
    ! one call at a time; the units never touch it)
    type(unit_result_t), allocatable :: kept(:)    !! results by unit, until handed on
    logical, allocatable :: done(:)                !! unit delivered or restored
    logical, allocatable :: restored(:)            !! unit read from the journal
    logical, allocatable :: on_disk(:)             !! its result is read from the journal
                                                   !! in its turn (restored, or set aside)
    integer(int64), allocatable :: line_at(:)      !! where its line starts in journal_file
    integer, allocatable :: line_len(:)            !! its length (without the new line)
    integer(int64) :: held = 0                     !! bytes of the results in kept
    integer(int64) :: hold_limit = 0               !! hold_bytes() of this batch
    character(len=:), allocatable :: restore_problem  !! a unit that did not read back
    integer :: next_log = 1                        !! the first unit not yet handed on
    procedure(unit_deliver), pointer :: consumer => null()  !! batch_run's `consume`
    type(c_ptr) :: journal = c_null_ptr            !! the open journal (null: none)
    character(len=:), allocatable :: journal_file  !! its path (removed by batch_commit)
    logical :: journal_failed = .false.            !! a write failed (warned once)
    integer(int64) :: journal_end = 1              !! where its next line goes (its size + 1)
    integer :: reader = -1                         !! journal_file open for reading (-1: not)
    integer(int64) :: last_sync = -1               !! clock count of the last fsync (-1: none)
    !> Seconds between two fsyncs of the journal (every line is flushed to the system
    !> at once; see put_line).
    real, parameter :: SYNC_INTERVAL = 1.0
    !> MiB of results held while they wait for an earlier unit (a long record keeps the
    !> short ones after it waiting), unless SEISPULSE_BATCH_HOLD_MB says otherwise: beyond
    !> this a result waits in the journal, which has it already, and is read back in its
    !> turn, so memory stays bounded.
    integer, parameter :: HOLD_MB = 16

contains

    !> The journal of the run with output prefix `prefix`: <prefix>.journal
    !> ('out/case1' -> out/case1.journal; a prefix that is a directory, 'out/', ->
    !> out/seispulse.journal). Its directory is created as the tables' is.
    pure function journal_path(prefix) result(path)
        character(len=*), intent(in) :: prefix   !! output prefix of &run
        character(len=:), allocatable :: path
        integer :: n
        n = len_trim(prefix)
        if (n == 0) then
            path = 'seispulse.journal'
        else if (prefix(n:n) == '/') then
            path = prefix(1:n)//'seispulse.journal'
        else
            path = prefix(1:n)//'.journal'
        end if
    end function journal_path

    !> Compute the units of a batch and hand their results to `consume` (on the root),
    !> once each, in unit order, as soon as every unit before it is done; a result is
    !> released once consumed. Units are those of size(keys); with `restart = .true.` in
    !> &run those in the journal of an earlier, killed run of the same input are restored
    !> instead of computed (one line on stderr says how many). Each computed unit's log
    !> (its stderr lines) is printed in unit order, before the unit is consumed. `consume`
    !> runs one call at a time, in the critical section seispulse_text (it may build
    !> texts while units run). A restored unit is read again from the journal when its
    !> turn comes (read_journal only checks it). stat /= 0: the journal is refused
    !> (another run's, or damaged), errmsg "journal:line: problem (what to do)", nothing
    !> was computed or consumed; or a restored unit did not read back (the journal changed
    !> during the run), errmsg naming it, the units from it on were not consumed. On a
    !> worker rank (MPI) this routine computes what the root sends it, then ends the
    !> process (status 0).
    subroutine batch_run(path, prefix, analysis, keys, work, consume, stat, errmsg)
        character(len=*), intent(in) :: path       !! the input file (its bytes enter the
                                                   !! fingerprint)
        character(len=*), intent(in) :: prefix     !! output prefix (the journal's place)
        character(len=*), intent(in) :: analysis   !! 'newmark', 'sdof' (log lines, fingerprint)
        character(len=*), intent(in) :: keys(:)    !! one per unit: what identifies it
        procedure(unit_work) :: work               !! computes one unit (concurrently)
        procedure(unit_deliver) :: consume         !! takes each result, in unit order
        integer, intent(out) :: stat               !! 0, or 1 (journal refused)
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=16) :: fp
        character(len=:), allocatable :: jpath, msg
        integer, allocatable :: todo(:)
        integer :: n, i, nrest
        logical :: exists

        stat = 0
        errmsg = ''
        if (.not. par_root()) then
            ! a worker: the root hands out the units; then this process ends
            allocate(todo(0))
            call par_run_units(todo, work, deliver)
            call par_finalize()
            flush(output_unit)
            flush(error_unit)
            call c_exit(0_c_int)
        end if

        n = size(keys)
        jpath = journal_path(prefix)
        call fingerprint(path, analysis, keys, fp, stat, msg)
        if (stat /= 0) then
            errmsg = msg
            call release_workers()
            return
        end if
        if (allocated(kept)) deallocate(kept)
        if (allocated(done)) deallocate(done)
        if (allocated(restored)) deallocate(restored, on_disk, line_at, line_len)
        allocate(kept(n), done(n), restored(n), on_disk(n), line_at(n), line_len(n))
        done = .false.
        restored = .false.
        held = 0
        hold_limit = hold_bytes()
        line_at = 0
        line_len = 0
        restore_problem = ''
        next_log = 1
        journal_failed = .false.

        inquire(file=jpath, exist=exists)
        nrest = 0
        if (run_restart()) then
            if (exists) then
                call read_journal(jpath, fp, n, stat, errmsg)
                if (stat /= 0) then
                    call release_workers()
                    return
                end if
                nrest = count(restored)
                write(error_unit, '(a)') analysis//': '//int_str(nrest)//' of ' &
                    //int_str(n)//' units restored from '//jpath
            else
                write(error_unit, '(a)') analysis//': restart: no journal '//jpath &
                    //': all '//int_str(n)//' units are computed'
            end if
            flush(error_unit)
        else if (exists) then
            write(error_unit, '(a)') 'warning: '//jpath//': the journal of an earlier run ' &
                //'is replaced (restart = .true. in &run resumes from it)'
            flush(error_unit)
        end if
        done = restored
        on_disk = restored

        journal_file = jpath
        call open_journal(jpath, fp, n)
        todo = pack([(i, i = 1, n)], .not. restored)
        consumer => consume
        call hand_on()
        call par_run_units(todo, work, deliver)
        consumer => null()
        if (c_associated(journal)) then
            if (c_fclose(journal) /= 0) call journal_warning()
            journal = c_null_ptr
        end if
        if (reader /= -1) close(reader, iostat=i)
        reader = -1
        deallocate(kept, done, restored, on_disk, line_at, line_len)
        if (len(restore_problem) > 0) then
            stat = 1
            errmsg = restore_problem//' (delete the journal, or run with restart = ' &
                     //'.false. in &run to compute every unit again)'
        end if
    end subroutine batch_run

    !> After the tables of the run are committed: remove its journal (if any).
    subroutine batch_commit()
        if (.not. allocated(journal_file)) return
        call remove_file(journal_file)
        call remove_file(journal_file//'.tmp')
        deallocate(journal_file)
    end subroutine batch_commit

    !> After an error (exit status 2, no table written): the journal this run started is
    !> removed with the other outputs, unless the run was a restart (restart = .true.:
    !> it stays, to resume from once the problem is fixed). A journal this run did not
    !> start (an input error before the batch, a journal refused) is never touched.
    subroutine batch_discard()
        if (.not. allocated(journal_file)) return
        if (run_restart()) return
        call batch_commit()
    end subroutine batch_discard

    !> Under MPI the workers wait in par_run_units: hand them no unit, so they end.
    subroutine release_workers()
        integer :: none(0)
        call par_run_units(none, nothing, deliver)
    end subroutine release_workers

    !> The work of no unit (release_workers never calls it).
    subroutine nothing(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(out) :: res
        res%text = int_str(i)
    end subroutine nothing

    !> On the root, one unit at a time: journal it, keep it (or, out of turn with
    !> hold_limit bytes held already, leave it in the journal), hand on the units now due.
    subroutine deliver(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(in) :: res
        character(len=:), allocatable :: line
        integer(int64) :: at
        if (i < 1 .or. i > size(kept)) return
        if (done(i)) return
        done(i) = .true.
        at = journal_end
        line = ''
        if (c_associated(journal)) then
            line = unit_line(i, res)
            call put_line(line)
        end if
        if (i /= next_log .and. held + result_bytes(res) > hold_limit .and. &
            c_associated(journal) .and. .not. journal_failed) then
            on_disk(i) = .true.
            line_at(i) = at
            line_len(i) = len(line)
        else
            kept(i) = res
            held = held + result_bytes(res)
        end if
        call hand_on()
    end subroutine deliver

    !> The units from next_log on, in order, up to the first unit not yet done: read it
    !> back if it waits in the journal, print its log (a restored unit prints nothing:
    !> one line said how many were restored), hand it to the consumer, release it. After
    !> a unit that does not read back (restore_problem) nothing more is handed on.
    subroutine hand_on()
        type(unit_result_t) :: empty
        do while (next_log <= size(done))
            if (.not. done(next_log)) exit
            if (on_disk(next_log)) then
                call load_unit(next_log, kept(next_log))
            else
                held = held - result_bytes(kept(next_log))
            end if
            if (.not. restored(next_log) .and. allocated(kept(next_log)%log)) then
                if (len(kept(next_log)%log) > 0) then
                    write(error_unit, '(a)') kept(next_log)%log
                    flush(error_unit)
                end if
            end if
            if (len(restore_problem) == 0) then
                !$omp critical (seispulse_text)
                call consumer(next_log, kept(next_log))
                !$omp end critical (seispulse_text)
            end if
            kept(next_log) = empty
            next_log = next_log + 1
        end do
    end subroutine hand_on

    !> Bytes of results a batch may hold out of turn: SEISPULSE_BATCH_HOLD_MB (MiB, an
    !> integer >= 0; 0: every result out of turn waits in the journal) if it is set to
    !> one, else HOLD_MB.
    integer(int64) function hold_bytes() result(b)
        character(len=32) :: text
        integer :: length, status, mb, ios
        b = int(HOLD_MB, int64) * 1048576_int64
        call get_environment_variable('SEISPULSE_BATCH_HOLD_MB', text, length, status)
        if (status /= 0 .or. length == 0) return
        read(text, *, iostat=ios) mb
        if (ios == 0 .and. mb >= 0) b = int(mb, int64) * 1048576_int64
    end function hold_bytes

    !> Bytes a result takes in memory (about).
    pure integer(int64) function result_bytes(res) result(b)
        type(unit_result_t), intent(in) :: res
        b = 64
        if (allocated(res%values)) b = b + 8_int64 * size(res%values)
        if (allocated(res%text)) b = b + len(res%text)
        if (allocated(res%log)) b = b + len(res%log)
    end function result_bytes

    ! ------------------------------------------------------------------------------
    ! Writing the journal
    ! ------------------------------------------------------------------------------

    !> Start the journal: the header and the restored units' lines (copied from the old
    !> journal) go to <jpath>.tmp, forced to disk, which then replaces <jpath> (rename: a
    !> kill leaves the old journal or the new one, never half of one); line_at then
    !> points into the new one. The stream stays open for the units to come;
    !> a journal that cannot be written is a warning (the run goes on without it).
    subroutine open_journal(jpath, fp, n)
        character(len=*), intent(in) :: jpath
        character(len=16), intent(in) :: fp
        integer, intent(in) :: n
        integer(int64), allocatable :: new_at(:)
        character(len=:), allocatable :: line
        character(len=512) :: iomsg
        integer :: i, last, u, stat
        journal = c_null_ptr
        call make_parent_dir(jpath)
        journal = c_fopen(jpath//'.tmp'//c_null_char, 'wb'//c_null_char)
        if (.not. c_associated(journal)) then
            call journal_warning()
            return
        end if
        journal_end = 1
        last = 0
        do i = 1, n
            if (restored(i)) last = i
        end do
        ! forced to disk once, after the last of these lines
        line = MAGIC//' '//int_str(JOURNAL_FORMAT)//' '//fp//' '//int_str(n)
        call put_line(line, last == 0)
        new_at = line_at
        if (last > 0) then
            ! the restored units' lines, copied from the old journal, and where they go
            open(newunit=u, file=jpath, access='stream', form='unformatted', action='read', &
                 status='old', iostat=stat, iomsg=iomsg)
            if (stat == 0) then
                do i = 1, n
                    if (stat /= 0 .or. journal_failed) exit
                    if (.not. restored(i)) cycle
                    deallocate(line)
                    allocate(character(len=line_len(i)) :: line)
                    read(u, pos=line_at(i), iostat=stat, iomsg=iomsg) line
                    if (stat /= 0) exit
                    new_at(i) = journal_end
                    call put_line(line, i == last)
                end do
                close(u, iostat=i)
            end if
            ! (the old journal was read a moment ago: this cannot fail but by accident)
            if (stat /= 0) call journal_warning()
        end if
        if (journal_failed) return
        if (c_rename(jpath//'.tmp'//c_null_char, jpath//c_null_char) /= 0) then
            ! the old journal stays where it was (restored units are read from it)
            call journal_warning()
        else if (last > 0) then
            line_at = new_at
        end if
    end subroutine open_journal

    !> Write one line and its new line, then (unless `sync` is false: more lines follow at
    !> once) force it to disk.
    subroutine put_line(line, sync)
        character(len=*), intent(in) :: line
        logical, intent(in), optional :: sync
        integer(c_size_t) :: nb
        if (.not. c_associated(journal)) return
        nb = int(len(line) + 1, c_size_t)
        if (c_fwrite(line//new_line('a'), 1_c_size_t, nb, journal) /= nb) then
            call journal_warning()
            return
        end if
        journal_end = journal_end + int(nb, int64)
        if (present(sync)) then
            if (.not. sync) return
        end if
        if (journal_failed) then
            return
        else if (c_fflush(journal) /= 0) then
            call journal_warning()
            return
        end if
        ! the line is now with the operating system (a killed run keeps it); to disk (a
        ! power loss keeps it) at most once per SYNC_INTERVAL: an fsync costs milliseconds,
        ! as much as a short record, and a power loss then costs at most that much work
        if (.not. sync_due()) return
        if (c_fsync(c_fileno(journal)) /= 0) call journal_warning()
    end subroutine put_line

    !> Whether SYNC_INTERVAL has passed since the journal was last forced to disk (the
    !> first call: yes); if so, the clock restarts now.
    logical function sync_due()
        integer(int64) :: now, rate
        call system_clock(now, rate)
        sync_due = last_sync < 0 .or. real(now - last_sync) >= SYNC_INTERVAL * real(rate)
        if (sync_due) last_sync = now
    end function sync_due

    !> A journal write failed: say so once; the run goes on without the journal.
    subroutine journal_warning()
        if (journal_failed) return
        journal_failed = .true.
        write(error_unit, '(a)') 'warning: cannot write the journal '//journal_file &
            //': the run goes on without it (a restart computes the units it misses)'
        flush(error_unit)
        if (c_associated(journal)) then
            if (c_fclose(journal) /= 0) continue
        end if
        journal = c_null_ptr
    end subroutine journal_warning

    !> The journal line of unit i: "u <i> <n> <hex>... <text> <log> <checksum>".
    function unit_line(i, res) result(line)
        integer, intent(in) :: i
        type(unit_result_t), intent(in) :: res
        character(len=:), allocatable :: line, head, text, log
        type(fnv_t) :: h
        integer :: nv, k, pos
        nv = -1
        if (allocated(res%values)) nv = size(res%values)
        head = 'u '//int_str(i)//' '//int_str(nv)
        text = escaped(res%text, allocated(res%text))
        log = escaped(res%log, allocated(res%log))
        allocate(character(len=len(head) + 17 * max(nv, 0) + 2 + len(text) + len(log) &
                 + 17) :: line)
        line(1:len(head)) = head
        pos = len(head)
        do k = 1, nv
            line(pos + 1:pos + 17) = ' '//hex_real(res%values(k))
            pos = pos + 17
        end do
        line(pos + 1:pos + 2 + len(text) + len(log)) = ' '//text//' '//log
        pos = pos + 2 + len(text) + len(log)
        call fnv_feed(h, line(1:pos))
        line(pos + 1:) = ' '//fnv_hex(h)
    end function unit_line

    !> '-' for an absent string, else '=' and the string with %, blanks, control
    !> characters and DEL as %XX.
    function escaped(s, present_) result(e)
        character(len=*), intent(in) :: s
        logical, intent(in) :: present_
        character(len=:), allocatable :: e
        integer :: i, n, c
        if (.not. present_) then
            e = '-'
            return
        end if
        n = 1
        do i = 1, len(s)
            n = n + merge(3, 1, needs_escape(s(i:i)))
        end do
        allocate(character(len=n) :: e)
        e(1:1) = '='
        n = 1
        do i = 1, len(s)
            if (needs_escape(s(i:i))) then
                c = ichar(s(i:i))
                e(n + 1:n + 3) = '%'//HEX(c / 16 + 1:c / 16 + 1)//HEX(mod(c, 16) + 1:mod(c, 16) + 1)
                n = n + 3
            else
                e(n + 1:n + 1) = s(i:i)
                n = n + 1
            end if
        end do
    end function escaped

    pure logical function needs_escape(ch)
        character(len=1), intent(in) :: ch
        needs_escape = ch == '%' .or. ch == ' ' .or. ichar(ch) < 32 .or. ichar(ch) == 127
    end function needs_escape

    ! ------------------------------------------------------------------------------
    ! Reading the journal
    ! ------------------------------------------------------------------------------

    !> Check the journal `jpath` of this run (fingerprint fp, n units): restored(i) for each
    !> unit it holds, and where its line is (line_at, line_len). The file is read through
    !> a buffer of CHUNK bytes (a longer line by read_line) and each unit is parsed to be
    !> checked, not kept: hand_on reads it back in its turn (a restart does not hold the
    !> journal in memory). stat /= 0 with errmsg "jpath:line: problem (...)" for a
    !> foreign or damaged journal.
    subroutine read_journal(jpath, fp, n, stat, errmsg)
        character(len=*), intent(in) :: jpath
        character(len=16), intent(in) :: fp
        integer, intent(in) :: n
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: line, problem
        character(len=CHUNK) :: buf
        character(len=512) :: iomsg
        integer(int64) :: start, size8, buf_at
        integer :: u, lineno, i, k, off, buf_n
        type(unit_result_t) :: res
        logical :: complete

        stat = 0
        errmsg = ''
        open(newunit=u, file=jpath, access='stream', form='unformatted', action='read', &
             status='old', iostat=stat, iomsg=iomsg)
        if (stat /= 0) then
            call refuse(1, 'cannot read it: '//trim(iomsg))
            return
        end if
        inquire(unit=u, size=size8)
        lineno = 0
        start = 1
        buf_at = 1                 ! buf(1:buf_n) holds the bytes from buf_at on
        buf_n = 0
        do while (start <= size8)
            ! the line at start: in the buffer, else from a buffer refilled at start, else
            ! (longer than the buffer) read whole
            k = 0
            off = int(start - buf_at)
            if (start < buf_at + buf_n) k = index(buf(off + 1:buf_n), new_line('a'))
            if (k == 0) then
                buf_at = start
                off = 0
                buf_n = int(min(size8 - start + 1, int(CHUNK, int64)))
                read(u, pos=start, iostat=stat, iomsg=iomsg) buf(1:buf_n)
                if (stat == 0) k = index(buf(1:buf_n), new_line('a'))
            end if
            if (stat == 0 .and. k > 0) then
                line = buf(off + 1:off + k - 1)
                complete = .true.
            else if (stat == 0) then
                call read_line(u, start, line, complete, stat, iomsg)
            end if
            if (stat /= 0) then
                call refuse(lineno + 1, 'cannot read it: '//trim(iomsg))
                exit
            end if
            ! an unterminated last line: the run was killed while writing it; that unit
            ! is computed again
            if (.not. complete) exit
            lineno = lineno + 1
            if (lineno == 1) then
                call check_header(line, fp, n, problem)
            else
                call parse_unit_line(line, n, i, res, problem)
                if (len(problem) == 0) then
                    if (restored(i)) then
                        problem = 'unit '//int_str(i)//' given twice'
                    else
                        restored(i) = .true.
                        line_at(i) = start
                        line_len(i) = len(line)
                    end if
                end if
            end if
            if (len(problem) > 0) then
                call refuse(lineno, problem)
                exit
            end if
            start = start + len(line) + 1
        end do
        close(u, iostat=i)
        if (stat == 0 .and. lineno == 0) &
            call refuse(1, 'no header line (not a complete seispulse journal)')

    contains

        subroutine refuse(line, what)
            integer, intent(in) :: line
            character(len=*), intent(in) :: what
            stat = 1
            errmsg = jpath//':'//int_str(line)//': '//what//' (delete the journal, or run ' &
                     //'with restart = .false. in &run to compute every unit again)'
            restored = .false.
        end subroutine refuse

    end subroutine read_journal

    !> The line of stream unit u that starts at byte `start` (without its new line): its
    !> end is found a chunk at a time, then it is read whole. complete: a new line ends it
    !> (else the file ends first; line is then ''). stat /= 0: a read error (iomsg).
    subroutine read_line(u, start, line, complete, stat, iomsg)
        integer, intent(in) :: u
        integer(int64), intent(in) :: start
        character(len=:), allocatable, intent(out) :: line
        logical, intent(out) :: complete
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: iomsg
        character(len=CHUNK) :: buf
        integer(int64) :: size8, at, n
        integer :: m, k
        line = ''
        complete = .false.
        stat = 0
        inquire(unit=u, size=size8)
        at = start
        do while (at <= size8)
            m = int(min(size8 - at + 1, int(CHUNK, int64)))
            read(u, pos=at, iostat=stat, iomsg=iomsg) buf(1:m)
            if (stat /= 0) return
            k = index(buf(1:m), new_line('a'))
            if (k > 0) then
                n = at + k - 1 - start
                if (n > int(huge(0), int64)) then
                    stat = 1
                    iomsg = 'a line longer than 2 GB'
                    return
                end if
                deallocate(line)
                allocate(character(len=int(n)) :: line)
                if (n > 0) read(u, pos=start, iostat=stat, iomsg=iomsg) line
                complete = stat == 0
                return
            end if
            at = at + m
        end do
    end subroutine read_line

    !> Unit i read back from its journal line (restored, or set aside by deliver; checked
    !> when it was read or written): exactly its bytes and the new line after them. A line
    !> that no longer reads back (the journal changed during the run) leaves res empty
    !> and restore_problem set.
    subroutine load_unit(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(out) :: res
        character(len=:), allocatable :: line, problem
        character(len=512) :: iomsg
        integer :: j, stat
        problem = ''
        stat = 0
        if (reader == -1) open(newunit=reader, file=journal_file, access='stream', &
                               form='unformatted', action='read', status='old', &
                               iostat=stat, iomsg=iomsg)
        if (stat /= 0) reader = -1
        if (stat == 0) then
            allocate(character(len=line_len(i) + 1) :: line)
            read(reader, pos=line_at(i), iostat=stat, iomsg=iomsg) line
        end if
        if (stat /= 0) then
            problem = 'cannot read it again: '//trim(iomsg)
        else if (line(len(line):) /= new_line('a')) then
            problem = 'it changed during the run'
        else
            call parse_unit_line(line(1:line_len(i)), size(done), j, res, problem)
            if (len(problem) == 0 .and. j /= i) problem = 'it changed during the run'
        end if
        if (len(problem) > 0 .and. len(restore_problem) == 0) &
            restore_problem = journal_file//': unit '//int_str(i)//': '//problem
    end subroutine load_unit

    !> The header "seispulse-journal <format> <fingerprint> <units>" of this run?
    !> problem: '' if it is, else what differs.
    subroutine check_header(line, fp, n, problem)
        character(len=*), intent(in) :: line
        character(len=16), intent(in) :: fp
        integer, intent(in) :: n
        character(len=:), allocatable, intent(out) :: problem
        character(len=:), allocatable :: w
        integer :: pos, fmt, units
        logical :: ok
        problem = ''
        pos = 1
        call next_word(line, pos, w)
        if (w /= MAGIC) then
            problem = 'not a seispulse journal (its first line does not start with ' &
                      //MAGIC//')'
            return
        end if
        call next_word(line, pos, w)
        call read_int(w, fmt, ok)
        if (.not. ok) then
            problem = 'damaged header (journal format '''//w//''')'
            return
        end if
        if (fmt /= JOURNAL_FORMAT) then
            problem = 'journal format '//int_str(fmt)//', this seispulse reads format ' &
                      //int_str(JOURNAL_FORMAT)//' only'
            return
        end if
        call next_word(line, pos, w)
        if (w /= fp) then
            problem = 'the journal of another run (fingerprint '//w//', this run''s is ' &
                      //fp//': the input file, the analysis, the record files or the ' &
                      //'seispulse version differ)'
            return
        end if
        call next_word(line, pos, w)
        call read_int(w, units, ok)
        if (.not. ok .or. pos <= len(line)) then
            problem = 'damaged header (the number of units)'
            return
        end if
        if (units /= n) problem = 'the journal of another run ('//int_str(units) &
            //' units, this run has '//int_str(n)//')'
    end subroutine check_header

    !> One unit line: check it and read unit i's result from it. problem: '' or what is
    !> wrong.
    subroutine parse_unit_line(line, n, i, res, problem)
        character(len=*), intent(in) :: line
        integer, intent(in) :: n
        integer, intent(out) :: i
        type(unit_result_t), intent(out) :: res
        character(len=:), allocatable, intent(out) :: problem
        character(len=:), allocatable :: w
        type(fnv_t) :: h
        integer :: pos, last, nv, k
        integer(int64) :: bits
        logical :: ok

        problem = ''
        last = index(line, ' ', back=.true.)
        if (last == 0) then
            problem = 'damaged line (no checksum)'
            return
        end if
        call fnv_feed(h, line(1:last - 1))
        if (line(last + 1:) /= fnv_hex(h)) then
            problem = 'damaged line (its checksum does not match)'
            return
        end if
        pos = 1
        call next_word(line(1:last - 1), pos, w)
        if (w /= 'u') then
            problem = 'damaged line (not a unit line)'
            return
        end if
        call next_word(line(1:last - 1), pos, w)
        call read_int(w, i, ok)
        if (.not. ok) then
            problem = 'damaged line (unit '''//w//''')'
            return
        end if
        if (i < 1 .or. i > n) then
            problem = 'unit '//int_str(i)//' out of range (this run has units 1 to ' &
                      //int_str(n)//')'
            return
        end if
        call next_word(line(1:last - 1), pos, w)
        call read_int(w, nv, ok)
        if (.not. ok .or. nv < -1) then
            problem = 'damaged line (number of values '''//w//''')'
            return
        end if
        if (nv >= 0) then
            allocate(res%values(nv))
            do k = 1, nv
                ! 16 hex digits and a blank (a text field follows the values), read in
                ! place: a journal holds millions of them
                ok = pos + 16 <= last - 1
                if (ok) ok = line(pos + 16:pos + 16) == ' '
                if (ok) call read_hex(line(pos:pos + 15), bits, ok)
                if (.not. ok) then
                    call next_word(line(1:last - 1), pos, w)
                    problem = 'damaged line (value '//int_str(k)//' '''//w//''')'
                    return
                end if
                res%values(k) = transfer(bits, 1.0_dp)
                pos = pos + 17
            end do
        end if
        call next_word(line(1:last - 1), pos, w)
        call unescape(w, res%text, ok)
        if (ok) then
            call next_word(line(1:last - 1), pos, w)
            call unescape(w, res%log, ok)
        end if
        if (.not. ok .or. pos <= last - 1) problem = 'damaged line (text fields)'
    end subroutine parse_unit_line

    !> The word of s at pos (up to the next blank or the end); pos moves past the blank.
    subroutine next_word(s, pos, w)
        character(len=*), intent(in) :: s
        integer, intent(inout) :: pos
        character(len=:), allocatable, intent(out) :: w
        integer :: k
        if (pos > len(s)) then
            w = ''
            return
        end if
        k = index(s(pos:), ' ')
        if (k == 0) then
            w = s(pos:)
            pos = len(s) + 1
        else
            w = s(pos:pos + k - 2)
            pos = pos + k
        end if
    end subroutine next_word

    !> A decimal integer (digits, optionally a leading '-', at most 9 digits).
    subroutine read_int(w, v, ok)
        character(len=*), intent(in) :: w
        integer, intent(out) :: v
        logical, intent(out) :: ok
        integer :: k, s
        v = 0
        s = 1
        if (len(w) > 0) then
            if (w(1:1) == '-') s = 2
        end if
        ok = len(w) >= s .and. len(w) - s < 9
        if (.not. ok) return
        ok = verify(w(s:), '0123456789') == 0
        if (.not. ok) return
        do k = s, len(w)
            v = 10 * v + (ichar(w(k:k)) - ichar('0'))
        end do
        if (s == 2) v = -v
    end subroutine read_int

    !> 16 lowercase hex digits as the 64 bits they spell.
    subroutine read_hex(w, bits, ok)
        character(len=*), intent(in) :: w
        integer(int64), intent(out) :: bits
        logical, intent(out) :: ok
        integer(int64) :: hi, lo
        integer :: k, d
        bits = 0
        ok = len(w) == 16
        if (.not. ok) return
        hi = 0
        lo = 0
        do k = 1, 16
            d = index(HEX, w(k:k)) - 1
            if (d < 0) then
                ok = .false.
                return
            end if
            if (k <= 8) then
                hi = 16 * hi + d
            else
                lo = 16 * lo + d
            end if
        end do
        bits = ior(ishft(hi, 32), lo)
    end subroutine read_hex

    !> The string of an escaped field ('-': absent; '=...': %XX decoded). ok: well formed.
    subroutine unescape(w, s, ok)
        character(len=*), intent(in) :: w
        character(len=:), allocatable, intent(out) :: s
        logical, intent(out) :: ok
        integer :: i, n, d1, d2
        ok = .true.
        if (w == '-') return
        ok = .false.
        if (len(w) < 1) return
        if (w(1:1) /= '=') return
        allocate(character(len=len(w)) :: s)
        n = 0
        i = 2
        do while (i <= len(w))
            if (w(i:i) == '%') then
                if (i + 2 > len(w)) return
                d1 = index(HEX, w(i + 1:i + 1)) - 1
                d2 = index(HEX, w(i + 2:i + 2)) - 1
                if (d1 < 0 .or. d2 < 0) return
                n = n + 1
                s(n:n) = char(16 * d1 + d2)
                i = i + 3
            else
                n = n + 1
                s(n:n) = w(i:i)
                i = i + 1
            end if
        end do
        s = s(1:n)
        ok = .true.
    end subroutine unescape

    ! ------------------------------------------------------------------------------
    ! Fingerprint and hashing
    ! ------------------------------------------------------------------------------

    !> FNV-1a 64 of the journal format, the seispulse version, the analysis, the bytes of
    !> the input file and the unit keys (each string preceded by its length), as hex.
    subroutine fingerprint(path, analysis, keys, fp, stat, errmsg)
        character(len=*), intent(in) :: path, analysis
        character(len=*), intent(in) :: keys(:)
        character(len=16), intent(out) :: fp
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(fnv_t) :: h
        character(len=CHUNK) :: buf
        character(len=512) :: iomsg
        integer(int64) :: size8, left
        integer :: u, i, m

        fp = ''
        errmsg = ''
        call feed_string(MAGIC//' '//int_str(JOURNAL_FORMAT))
        call feed_string(seispulse_version)
        call feed_string(analysis)
        inquire(file=path, size=size8)
        open(newunit=u, file=path, access='stream', form='unformatted', action='read', &
             status='old', iostat=stat, iomsg=iomsg)
        if (stat /= 0 .or. size8 < 0) then
            if (stat == 0) close(u)
            stat = 1
            errmsg = path//': cannot read the input file for the journal''s fingerprint: ' &
                     //trim(iomsg)
            return
        end if
        call fnv_feed(h, int_str(int(min(size8, int(huge(0), int64))))//':')
        left = size8
        do while (left > 0)
            m = int(min(left, int(CHUNK, int64)))
            read(u, iostat=stat, iomsg=iomsg) buf(1:m)
            if (stat /= 0) then
                close(u)
                stat = 1
                errmsg = path//': cannot read the input file for the journal''s ' &
                         //'fingerprint: '//trim(iomsg)
                return
            end if
            call fnv_feed(h, buf(1:m))
            left = left - m
        end do
        close(u)
        call feed_string(int_str(size(keys)))
        do i = 1, size(keys)
            call feed_string(trim(keys(i)))
        end do
        fp = fnv_hex(h)
        stat = 0

    contains

        subroutine feed_string(s)
            character(len=*), intent(in) :: s
            call fnv_feed(h, int_str(len(s))//':')
            call fnv_feed(h, s)
        end subroutine feed_string

    end subroutine fingerprint

    !> Hash the bytes of s into h (FNV-1a 64: xor the byte, multiply by the prime, in
    !> 32-bit limbs: (hi 2^32 + lo)(2^40 + 435) mod 2^64).
    pure subroutine fnv_feed(h, s)
        type(fnv_t), intent(inout) :: h
        character(len=*), intent(in) :: s
        integer(int64) :: t
        integer :: i
        do i = 1, len(s)
            h%lo = ieor(h%lo, int(ichar(s(i:i)), int64))
            t = h%lo * 435_int64
            h%hi = iand(h%hi * 435_int64 + h%lo * 256_int64 + ishft(t, -32), MASK32)
            h%lo = iand(t, MASK32)
        end do
    end subroutine fnv_feed

    !> The hash as 16 lowercase hex digits.
    pure function fnv_hex(h) result(s)
        type(fnv_t), intent(in) :: h
        character(len=16) :: s
        s = hex8(h%hi)//hex8(h%lo)
    end function fnv_hex

    !> A double's IEEE 754 bits as 16 lowercase hex digits.
    pure function hex_real(x) result(s)
        real(dp), intent(in) :: x
        character(len=16) :: s
        integer(int64) :: bits
        bits = transfer(x, bits)
        s = hex8(ibits(bits, 32, 32))//hex8(ibits(bits, 0, 32))
    end function hex_real

    !> 0 <= v < 2^32 as 8 hex digits.
    pure function hex8(v) result(s)
        integer(int64), intent(in) :: v
        character(len=8) :: s
        integer :: k, d
        do k = 8, 1, -1
            d = int(ibits(v, 4 * (8 - k), 4))
            s(k:k) = HEX(d + 1:d + 1)
        end do
    end function hex8

    ! ------------------------------------------------------------------------------
    ! Records as units
    ! ------------------------------------------------------------------------------

    !> The key of each record (one unit per record): the FNV-1a hash (16 hex digits: a
    !> key per record costs 16 bytes, whatever the length of its path) of the path
    !> opened, the file's size in bytes (-1: none), and how it is read and scaled
    !> (format, units, dt, scale, target PGA as exact bits, polarity, the PGA rounding).
    function record_keys(recs, slammer_rounding) result(keys)
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        character(len=16) :: keys(size(recs))
        type(fnv_t) :: h
        integer(int64) :: size8
        integer :: i
        logical :: exists
        do i = 1, size(recs)
            associate (r => recs(i))
                size8 = -1
                inquire(file=r%path, exist=exists)
                if (exists) inquire(file=r%path, size=size8)
                h = fnv_t()
                call fnv_feed(h, r%path//KEY_SEP//int_str(int(min(size8, int(huge(0), int64)))) &
                     //KEY_SEP//int_str(r%fmt)//KEY_SEP//int_str(r%units) &
                     //KEY_SEP//hex_real(r%dt)//hex_real(r%scale)//hex_real(r%target) &
                     //KEY_SEP//int_str(r%polarity)//KEY_SEP//merge('s', 'e', slammer_rounding))
                keys(i) = fnv_hex(h)
            end associate
        end do
    end function record_keys

    !> Put what happened to a record first in a unit's result: values(1:RECORD_VALUES)
    !> (res%values allocated by the caller with at least that many) and the first
    !> RECORD_FIELDS text fields (name, message).
    subroutine pack_record(o, res)
        type(record_out_t), intent(in) :: o
        type(unit_result_t), intent(inout) :: res
        res%values(1:RECORD_VALUES) = [merge(1.0_dp, 0.0_dp, o%ok), real(o%fmt, dp), &
                                       real(o%npts, dp), o%dt, o%pga_read, o%factor, o%pga]
        call add_field(res, o%name)
        call add_field(res, o%message)
    end subroutine pack_record

    !> The record_out_t that pack_record put into res.
    subroutine unpack_record(res, o)
        type(unit_result_t), intent(in) :: res
        type(record_out_t), intent(out) :: o
        o%ok = res%values(1) > 0.5_dp
        o%fmt = nint(res%values(2))
        o%npts = nint(res%values(3))
        o%dt = res%values(4)
        o%pga_read = res%values(5)
        o%factor = res%values(6)
        o%pga = res%values(7)
        o%name = get_field(res, 1)
        o%message = get_field(res, 2)
    end subroutine unpack_record

end module driver_batch
