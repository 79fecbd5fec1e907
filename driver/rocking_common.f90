!> Checks and helpers shared by the analyses that run a rocking body ('rocking' and
!> 'cylinder'): the run options t_max and rtol, the restitution and the model, where a
!> library message belongs, the pulse family of an overturning map, and the progress
!> lines of a long map. One code path, so that these keys mean and read the same in both.
module driver_rocking_common
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use seispulse, only: dp, pulse_t, pulse_validate, pulse_kind_from_name, SEISPULSE_SUCCESS, &
                         PULSE_RICKER, PULSE_MP, real_str, positive, in_closed, finite_at_least
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: located, join, given
    implicit none
    private

    public :: check_run_options, restitution_and_model, locate_run_message
    public :: map_kind, map_template, progress_t

    character(len=10), parameter :: model_names(2) = [character(len=10) :: 'nonlinear', &
        'linearized']

    !> A map prints progress once it has run this long (s), then at most every
    !> `progress_every` seconds.
    real(dp), parameter :: progress_after = 2.0_dp, progress_every = 3.0_dp

    !> Progress lines of a map computed row by row ("map: row i/n" on stderr).
    type :: progress_t
        integer(int64) :: c_start = 0, c_last = 0, rate = 1
        logical :: printed = .false.
    contains
        procedure :: start => progress_start
        procedure :: row => progress_row
        procedure :: done => progress_done
    end type progress_t

contains

    !> t_max > 0 (s) or +Inf, rtol in [1e-14, 1e-3]: errmsg (after `where`) about the
    !> first bad one, '' if none.
    subroutine check_run_options(where, t_max, rtol, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &group: "
        real(dp), intent(in) :: t_max, rtol
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (.not. positive(t_max)) then
            errmsg = where//'t_max = '//real_str(t_max)//': must be a number > 0 (s) or ' &
                     //'+Inf (no limit)'
        else if (.not. in_closed(rtol, 1.0e-14_dp, 1.0e-3_dp)) then
            errmsg = where//'rtol = '//real_str(rtol)//': must be in [1e-14, 1e-3]'
        end if
    end subroutine check_run_options

    !> The keys e (given in `group`: in [0, 1]; else e_run is left as it is) and model
    !> ('nonlinear' or 'linearized', case and blanks ignored; model receives the clean
    !> name). errmsg (after `where`) on failure, else ''.
    subroutine restitution_and_model(where, group, e, model, e_run, linearized, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &group: "
        type(nml_group), intent(in) :: group
        real(dp), intent(in) :: e                         !! the value read
        character(len=*), intent(inout) :: model
        real(dp), intent(inout) :: e_run                  !! restitution of the runs
        logical, intent(out) :: linearized
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: name
        errmsg = ''
        linearized = .false.
        if (given(group, 'e')) then
            if (.not. in_closed(e, 0.0_dp, 1.0_dp)) then
                errmsg = where//'e = '//real_str(e)//': the coefficient of restitution ' &
                         //'must be in [0, 1]'
                return
            end if
            e_run = e
        end if
        name = trim(lower(adjustl(model)))
        select case (name)
        case ('nonlinear')
            linearized = .false.
        case ('linearized')
            linearized = .true.
        case default
            errmsg = where//'model = '''//trim(model)//''': unknown model (allowed: ' &
                     //join(model_names)//')'
            return
        end select
        model = name
    end subroutine restitution_and_model

    !> Where a library message about a run belongs, by the key it starts with: &pulse
    !> (pulse_keys), the run's group (run_keys), else the body's group.
    function locate_run_message(path, msg, pulse_group, pulse_keys, run_group, run_keys, &
                                body_group) result(full_msg)
        character(len=*), intent(in) :: path, msg
        type(nml_group), intent(in) :: pulse_group, run_group, body_group
        character(len=*), intent(in) :: pulse_keys(:), run_keys(:)
        character(len=:), allocatable :: full_msg
        character(len=:), allocatable :: key
        integer :: k
        k = scan(msg, ' =:(')
        key = ''
        if (k > 1) key = msg(1:k - 1)
        if (any(pulse_keys == key)) then
            full_msg = located(path, pulse_group)//msg
        else if (any(run_keys == key)) then
            full_msg = located(path, run_group)//msg
        else
            full_msg = located(path, body_group)//msg
        end if
    end function locate_run_message

    !> The pulse family of a map: its PULSE_* code (not M&P). errmsg (after `where`) on
    !> failure, else ''.
    subroutine map_kind(where, kind, code, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        character(len=*), intent(in) :: kind
        integer, intent(out) :: code
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: st
        errmsg = ''
        msg = ''
        call pulse_kind_from_name(kind, code, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
        else if (code == PULSE_MP) then
            errmsg = where//'kind = '''//trim(kind)//''': maps take an acceleration pulse ' &
                     //'with a time scale (not mavroeidis_papageorgiou)'
        end if
    end subroutine map_kind

    !> The template of a map's pulse family at a unit time scale (f_p = 1, so t0 = t0 f_p),
    !> checked. errmsg (after `where`) on failure, else ''.
    subroutine map_template(where, code, beta, full, peak_frac, t0_periods, cycles, tpl, &
                            errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        integer, intent(in) :: code                       !! PULSE_* code
        real(dp), intent(in) :: beta, peak_frac, t0_periods, cycles
        logical, intent(in) :: full
        type(pulse_t), intent(out) :: tpl
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: st
        errmsg = ''
        msg = ''
        tpl = pulse_t(kind=code, amp=1.0_dp, duration=1.0_dp, beta=beta, full=full, &
                      peak_frac=peak_frac, freq=1.0_dp, t0=t0_periods, cycles=cycles)
        if (code == PULSE_RICKER .and. .not. finite_at_least(t0_periods, 0.0_dp)) then
            errmsg = where//'t0_periods = '//real_str(t0_periods)//': must be a finite ' &
                     //'number >= 0 (the centre of the wavelet times f_p)'
            return
        end if
        call pulse_validate(tpl, st, msg)
        if (st /= SEISPULSE_SUCCESS) errmsg = where//trim(msg)
    end subroutine map_template

    !> Start the clock of a map.
    subroutine progress_start(self)
        class(progress_t), intent(inout) :: self
        call system_clock(self%c_start, self%rate)
        self%c_last = self%c_start
        self%printed = .false.
    end subroutine progress_start

    !> After row i of n: "map: row i/n" once the map has run progress_after seconds, then
    !> at most every progress_every seconds (not after the last row).
    subroutine progress_row(self, i, n)
        class(progress_t), intent(inout) :: self
        integer, intent(in) :: i, n
        integer(int64) :: c_now
        real(dp) :: elapsed, rate
        call system_clock(c_now)
        rate = real(max(self%rate, 1_int64), dp)
        elapsed = real(c_now - self%c_start, dp) / rate
        if (i < n .and. elapsed >= progress_after .and. (.not. self%printed .or. &
            real(c_now - self%c_last, dp) / rate >= progress_every)) then
            write(error_unit, '(a, i0, a, i0)') 'map: row ', i, '/', n
            flush(error_unit)
            self%c_last = c_now
            self%printed = .true.
        end if
    end subroutine progress_row

    !> "map: row n/n (done)" if a progress line was printed.
    subroutine progress_done(self, n)
        class(progress_t), intent(in) :: self
        integer, intent(in) :: n
        if (.not. self%printed) return
        write(error_unit, '(a, i0, a, i0, a)') 'map: row ', n, '/', n, ' (done)'
        flush(error_unit)
    end subroutine progress_done

end module driver_rocking_common
