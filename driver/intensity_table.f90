!> The intensity table of analysis 'newmark' (&newmark intensity = .true.): one row per
!> record with its intensity measures (doc/intensity.md): PGA (g), PGV (m/s), PGD (m),
!> Arias intensity (m/s), CAV (m/s), D5-75, D5-95 (s), Tm (s), and the pseudo-spectral
!> acceleration (g, 5 % damping) at the periods `sa_periods` (s) if given. The record is
!> the one the sliding analysis uses: read, scaled, with its polarity (every measure is
!> the same for the record turned over). Table <output>_intensity; a record that cannot
!> be read, or whose measures fail, has NaN results and status failed. The numbers come from
!> seispulse_intensity; this module only checks, collects and writes.
module driver_intensity_table
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use, intrinsic :: iso_fortran_env, only: output_unit
    use seispulse, only: dp, shortest_str, int_str, SEISPULSE_SUCCESS, intensity_t, &
                         record_intensity, &
                         spectral_acceleration, sdof_validate
    use driver_input, only: list_length, value_name, list_item
    use driver_tables, only: table_t, table_open, table_comment, table_row, category_kind, &
                             status_names
    use driver_records, only: record_in_t, record_out_t, record_line, report
    use driver_echo, only: echo_unit
    use driver_unit_result, only: unit_result_t
    implicit none
    private

    public :: intensity_table_t, intensity_check, intensity_echo, intensity_start, &
              intensity_record, intensity_open, intensity_add, SA_DAMPING

    real(dp), parameter :: SA_DAMPING = 0.05_dp   !! damping ratio of the Sa columns

    !> Measures per row before the Sa columns.
    integer, parameter :: n_measures = 8

    !> The intensity table under construction.
    type :: intensity_table_t
        logical :: on = .false.                 !! intensity = .true.
        real(dp), allocatable :: periods(:)     !! Sa periods (s)
        real(dp), allocatable :: table(:, :)    !! record x (measures, Sa, status)
        character(len=1024), allocatable :: notes(:)  !! why a row failed ('' if it did not)
    end type intensity_table_t

contains

    !> Check `intensity` and `sa_periods` (the list, NaN-padded, as read) of &newmark.
    !> `where` prefixes messages ("file:line: &newmark: "); errmsg is empty on success.
    subroutine intensity_check(where, on, sa_given, sa_periods, itab, errmsg)
        character(len=*), intent(in) :: where
        logical, intent(in) :: on, sa_given
        real(dp), intent(in) :: sa_periods(:)
        type(intensity_table_t), intent(out) :: itab
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=1024) :: msg
        integer :: n, i, j, st
        errmsg = ''
        itab%on = on
        allocate(itab%periods(0))
        if (.not. sa_given) return
        if (.not. on) then
            errmsg = where//'sa_periods: only with intensity = .true. (the Sa columns of ' &
                     //'the intensity table)'
            return
        end if
        call list_length(sa_periods, 'sa_periods', n, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        do i = 1, n
            msg = ''
            call sdof_validate(sa_periods(i), SA_DAMPING, st, msg, &
                               period_name=value_name('sa_periods', i, n))
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//trim(msg)
                return
            end if
            ! any order; a period twice would give two columns of one name
            do j = 1, i - 1
                if (.not. abs(sa_periods(i) - sa_periods(j)) > 0.0_dp) then
                    errmsg = where//list_item('sa_periods', i)//' = '//shortest_str(sa_periods(i)) &
                             //': given twice (sa_periods('//int_str(j)//'); the table has ' &
                             //'one column per period)'
                    return
                end if
            end do
        end do
        itab%periods = sa_periods(1:n)
    end subroutine intensity_check

    !> Room for nrec rows, all NaN with status failed until computed.
    subroutine intensity_start(itab, nrec)
        type(intensity_table_t), intent(inout) :: itab
        integer, intent(in) :: nrec
        if (.not. itab%on) return
        allocate(itab%table(nrec, n_measures + size(itab%periods) + 1), itab%notes(nrec))
        itab%table = ieee_value(1.0_dp, ieee_quiet_nan)
        itab%table(:, size(itab%table, 2)) = 1.0_dp
        itab%notes = ''
    end subroutine intensity_start

    !> The row of record ir, read as accel (g) at step dt (s), with g (m/s^2); a
    !> failure goes to stderr at once (prefixed by `what`, "file:line: &records:
    !> files(2) = 'x'") and into the table's header. Rows of records not read stay NaN
    !> with status failed. With `log` (a unit of a batch) the failure goes to log%log
    !> instead of stderr.
    subroutine intensity_record(itab, ir, accel, dt, g, what, log)
        type(intensity_table_t), intent(inout) :: itab
        integer, intent(in) :: ir
        real(dp), intent(in) :: accel(:), dt, g
        character(len=*), intent(in) :: what
        type(unit_result_t), intent(inout), optional :: log  !! collects the stderr line
        type(intensity_t) :: im
        character(len=1024) :: msg
        real(dp) :: sa
        integer :: st, k
        if (.not. itab%on) return
        msg = ''
        call record_intensity(accel, dt, g, im, st, msg)
        if (st == SEISPULSE_SUCCESS) then
            itab%table(ir, 1:n_measures) = [im%pga, im%pgv, im%pgd, im%arias, im%cav, &
                                            im%d5_75, im%d5_95, im%tm]
            do k = 1, size(itab%periods)
                call spectral_acceleration(accel, dt, itab%periods(k), SA_DAMPING, g, sa, &
                                           st, msg)
                if (st /= SEISPULSE_SUCCESS) exit
                itab%table(ir, n_measures + k) = sa
            end do
        end if
        if (st /= SEISPULSE_SUCCESS) then
            itab%table(ir, :) = ieee_value(1.0_dp, ieee_quiet_nan)
            itab%table(ir, size(itab%table, 2)) = 1.0_dp
            itab%notes(ir) = 'intensity: '//trim(msg)
            call report(what//': intensity: '//trim(msg), log)
            return
        end if
        itab%table(ir, size(itab%table, 2)) = 0.0_dp
    end subroutine intensity_record

    !> The keys of the intensity table in effect, as a &newmark group (when it is on).
    subroutine intensity_echo(itab)
        type(intensity_table_t), intent(in) :: itab
        if (itab%on) call echo(size(itab%periods))
    contains
        subroutine echo(n)
            integer, intent(in) :: n
            logical :: intensity
            real(dp) :: sa_periods(n)
            namelist /newmark/ intensity, sa_periods
            intensity = .true.
            sa_periods = itab%periods
            write(echo_unit(), nml=newmark)
        end subroutine echo
    end subroutine intensity_echo

    !> Start the table <prefix>_intensity (when it is on): its columns and the header
    !> lines before the records'; intensity_add writes each record's line and row.
    !> stat /= 0: an output error (nothing is left).
    subroutine intensity_open(t, path, prefix, g, itab, stat, errmsg)
        type(table_t), intent(out) :: t
        character(len=*), intent(in) :: path, prefix
        real(dp), intent(in) :: g
        type(intensity_table_t), intent(in) :: itab
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=24), allocatable :: names(:), col_units(:), kinds(:)
        character(len=:), allocatable :: line
        integer :: k, np

        stat = 0
        errmsg = ''
        if (.not. itab%on) return
        np = size(itab%periods)
        allocate(names(n_measures + np + 2), col_units(n_measures + np + 2))
        names(1:n_measures + 1) = [character(len=24) :: 'record', 'pga', 'pgv', 'pgd', &
            'arias', 'cav', 'd5_75', 'd5_95', 'tm']
        col_units(1:n_measures + 1) = [character(len=24) :: '-', 'g', 'm/s', 'm', 'm/s', &
            'm/s', 's', 's', 's']
        do k = 1, np
            names(n_measures + 1 + k) = 'sa_T='//shortest_str(itab%periods(k))
            col_units(n_measures + 1 + k) = 'g'
        end do
        names(n_measures + np + 2) = 'status'
        col_units(n_measures + np + 2) = '-'
        allocate(kinds(n_measures + np + 2))
        kinds = ''
        kinds(n_measures + np + 2) = category_kind(status_names)
        call table_open(t, prefix, 'intensity', names, col_units, stat, errmsg, kinds=kinds, &
                        labelled=.true.)
        if (stat /= 0) return
        call table_comment(t, 'seispulse analysis newmark: intensity measures of each ' &
                           //'record (doc/intensity.md), one row per record')
        call table_comment(t, 'input: '//trim(path))
        call table_comment(t, 'the record as analysed (read, scaled, polarity), linear ' &
                           //'between samples; g = '//shortest_str(g) &
                           //' m/s2; pgv, pgd from rest at the first sample, true peaks')
        call table_comment(t, 'arias = pi/(2g) int a^2 dt; cav = int |a| dt; d5_75, d5_95 ' &
                           //'from the Husid curve (NaN without energy); tm: mean period, ' &
                           //'0.25-20 Hz')
        line = 'sa_T=...: pseudo-spectral acceleration (2 pi/T)^2 SD/g, damping ' &
               //shortest_str(SA_DAMPING)//'; status: ok, or failed (nan results)'
        if (np == 0) line = 'no sa_periods; status: ok, or failed (nan results)'
        call table_comment(t, line)
        call table_comment(t, 'records (index, file, format read, npts, dt (s), PGA as ' &
                           //'read (g), scale factor):')
    end subroutine intensity_open

    !> Record ir of the intensity table: its header line and its row (measures, Sa,
    !> status; `note`: why it failed, '' if it did not). failed: its status is failed.
    subroutine intensity_add(t, ir, r, o, row, note, failed)
        type(table_t), intent(inout) :: t
        integer, intent(in) :: ir
        type(record_in_t), intent(in) :: r
        type(record_out_t), intent(in) :: o
        real(dp), intent(in) :: row(:)
        character(len=*), intent(in) :: note
        logical, intent(out) :: failed
        character(len=:), allocatable :: line
        line = record_line(ir, r, o)
        if (o%ok .and. len_trim(note) > 0) line = line//'; FAILED: '//trim(note)
        call table_comment(t, line)
        call table_row(t, row, o%name)
        failed = row(size(row)) > 0.5_dp
    end subroutine intensity_add

end module driver_intensity_table
