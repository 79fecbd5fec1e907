!> Analysis 'sdof_beta' of the linear oscillator (doc/oscillator.md): the dynamic
!> coefficient of harmonic base motion.
!>
!> Group &sdof_beta (frequency ratios theta/omega as a list or a range, the damping
!> parameters gamma = 2 zeta, the damping model); table <output>_sdof_beta, beta (Eq.
!> 2.17/2.20) and the cosine law's 2|beta| (after Eq. 2.21; the from-rest maximum only
!> for gamma = 0) from seispulse_sdof_closed's dynamic_coefficient.
module driver_sdof_beta
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use seispulse, only: dp, SEISPULSE_SUCCESS, SEISPULSE_SINGULAR, dynamic_coefficient, &
                         BETA_HYSTERETIC, BETA_VISCOUS
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, located, join, read_optional, name_index
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_tables, only: write_tables, say_written
    use driver_sdof_common, only: max_periods, max_dampings, check_list
    use driver_axis, only: axis_values
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_sdof_beta, sdof_beta_groups, sdof_beta_tables

    !> Groups this analysis reads (besides &run).
    character(len=12), parameter :: sdof_beta_groups(1) = [character(len=12) :: 'sdof_beta']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=9), parameter :: sdof_beta_tables(1) = [character(len=9) :: 'sdof_beta']

    character(len=12), parameter :: beta_keys(6) = [character(len=12) :: 'ratios', &
        'ratio_range', 'ratio_count', 'spacing', 'gamma', 'model']
    character(len=10), parameter :: model_names(2) = [character(len=10) :: 'hysteretic', &
        'viscous']

    !> gamma = 2 zeta when none is given.
    real(dp), parameter :: default_gamma = 0.1_dp

    ! namelist variables (defaults are set in set_defaults)
    real(dp) :: ratios(max_periods), ratio_range(2), gamma(max_dampings)
    integer :: ratio_count
    character(len=32) :: spacing, model
    namelist /sdof_beta/ ratios, ratio_range, ratio_count, spacing, gamma, model

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        ratios = nan
        ratio_range = nan
        ratio_count = 0
        spacing = 'linear'
        gamma = nan
        model = 'hysteretic'
    end subroutine set_defaults

    subroutine read_beta(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=sdof_beta, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=sdof_beta, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_beta

    !> Read and check &sdof_beta, tabulate the dynamic coefficient, write the table;
    !> print where it went. stat > 0 with errmsg on an input or output error.
    subroutine run_sdof_beta(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gb
        character(len=:), allocatable :: where, grid
        real(dp), allocatable :: axis(:), gammas(:), table(:, :)
        character(len=512) :: files(2)
        character(len=1024) :: comments(6), msg
        real(dp) :: nan, b, bc
        integer :: imodel, nr, ng, i, j, row, st

        call set_defaults()
        call read_optional(path, groups, 'sdof_beta', beta_keys, read_beta, gb, stat, errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'sdof_beta') == 0) then
            errmsg = missing_group(path, 'sdof_beta')//' (it gives the frequency ratios ' &
                     //'theta/omega: ratios = a list, or ratio_range = min, max with ' &
                     //'ratio_count)'
            return
        end if
        where = located(path, gb)
        call axis_values(gb, 'ratios', 'ratio', ratios, ratio_range, ratio_count, spacing, &
                         .false., .false., max_periods, axis, grid, errmsg)
        if (len(errmsg) == 0 .and. size(axis) == 0) errmsg = 'ratios: missing (give ' &
            //'ratios = a list of theta/omega, or ratio_range = min, max with ratio_count)'
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        call check_list(gb, 'gamma', gamma, default_gamma, 0.0_dp, huge(1.0_dp), .false., &
                        'a finite number >= 0 (gamma = 2 zeta)', gammas, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        select case (name_index(model, model_names))
        case (1)
            imodel = BETA_HYSTERETIC
        case (2)
            imodel = BETA_VISCOUS
        case default
            errmsg = where//'model = '''//trim(model)//''': unknown model (allowed: ' &
                     //join(model_names)//')'
            return
        end select

        ! --- echo the effective input
        call echo_beta(axis, gammas, model_names(imodel))

        ! --- compute
        nan = ieee_value(nan, ieee_quiet_nan)
        nr = size(axis)
        ng = size(gammas)
        allocate(table(nr * ng, 4))
        do j = 1, ng
            do i = 1, nr
                row = (j - 1) * nr + i
                msg = ''
                call dynamic_coefficient(axis(i), gammas(j), imodel, b, st, msg, beta_cos=bc)
                if (st == SEISPULSE_SINGULAR) then
                    ! undamped resonance: |beta| is infinite, its sign undefined
                    b = nan
                    bc = ieee_value(bc, ieee_positive_inf)
                else if (st /= SEISPULSE_SUCCESS) then
                    errmsg = where//trim(msg)
                    return
                end if
                table(row, :) = [gammas(j), axis(i), b, bc]
            end do
        end do

        ! --- write
        comments(1) = 'seispulse analysis sdof_beta: dynamic coefficient of harmonic base ' &
                      //'motion against the frequency ratio theta/omega, one row per gamma ' &
                      //'and ratio'
        comments(2) = 'input: '//trim(path)
        comments(3) = 'ratios: '//grid//'; model = '//trim(model_names(imodel))//'; gamma = ' &
                      //'2 zeta (zeta: the viscous damping ratio)'
        comments(4) = 'hysteretic (the book''s Eq. 2.20, square root restored): beta = ' &
                      //'1/sqrt((1 - r^2)^2 + gamma^2); viscous: 1/sqrt((1 - r^2)^2 + ' &
                      //'(gamma r)^2); both 1/gamma at r = 1'
        comments(5) = 'gamma = 0: the signed 1/(1 - r^2) (Eq. 2.17, negative above ' &
                      //'resonance); at r = 1 beta = nan (infinite, sign undefined) and ' &
                      //'beta_cos = inf'
        comments(6) = 'beta_cos = 2|beta|: the cosine law from rest (after Eq. 2.21); ' &
                      //'max S = k_c beta Q (Eq. 2.19)'
        call write_tables(prefix, 'sdof_beta', comments, &
            [character(len=11) :: 'gamma', 'theta/omega', 'beta', 'beta_cos'], &
            [character(len=11) :: '-', '-', '-', '-'], table, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('sdof_beta table', files)

    end subroutine run_sdof_beta

    !> &sdof_beta with the values in use.
    subroutine echo_beta(values, gammas, model_name)
        real(dp), intent(in) :: values(:), gammas(:)
        character(len=*), intent(in) :: model_name
        real(dp) :: ratios(size(values)), gamma(size(gammas))
        character(len=10) :: model
        namelist /sdof_beta/ ratios, gamma, model
        ratios = values
        gamma = gammas
        model = model_name
        write(echo_unit(), nml=sdof_beta)
    end subroutine echo_beta

end module driver_sdof_beta
