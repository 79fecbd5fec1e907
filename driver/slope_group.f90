!> The &slope group of analysis 'newmark' (methods 'decoupled' and 'coupled'): the
!> flexible sliding mass above the slip surface, its keys, defaults, reading, checks,
!> echo and header line. The mass is validated by the library (flexible_mass_validate,
!> doc/flexible.md section 9); the driver only adds the file, line, group and key.
module driver_slope
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, int_str, flexible_mass_t, &
                         flexible_mass_validate, flexible_soil_name, flexible_soil_code, &
                         SOIL_LINEAR, SOIL_EQUIVALENT_LINEAR
    use driver_namelist_scan, only: nml_group
    use driver_namelist_scan, only: lower
    use driver_input, only: located, given
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: slope_keys, slope_defaults, read_slope, check_slope, echo_slope, slope_line

    character(len=14), parameter :: slope_keys(7) = [character(len=14) :: 'height', 'vs', &
        'vs_base', 'damping', 'soil', 'ref_strain_pct', 'max_iter']

    ! namelist variables (defaults are set in slope_defaults)
    real(dp) :: height, vs, vs_base, damping, ref_strain_pct
    character(len=32) :: soil
    integer :: max_iter
    namelist /slope/ height, vs, vs_base, damping, soil, ref_strain_pct, max_iter

contains

    !> The defaults of &slope, set before it is read (those of flexible_mass_t; height,
    !> vs and vs_base have none).
    subroutine slope_defaults()
        type(flexible_mass_t) :: d
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        height = nan
        vs = nan
        vs_base = nan
        damping = d%damping
        soil = flexible_soil_name(d%soil)
        ref_strain_pct = d%ref_strain_pct
        max_iter = d%max_iter
    end subroutine slope_defaults

    !> Reader of &slope for driver_input's read_group.
    subroutine read_slope(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=slope, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=slope, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_slope

    !> Check &slope (read by read_slope) and fill mass. errmsg is empty on success; a
    !> key of the equivalent-linear model given with soil = 'linear' is a warning.
    subroutine check_slope(path, gs, mass, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gs
        type(flexible_mass_t), intent(out) :: mass
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=1024) :: msg
        character(len=14), parameter :: required(3) = [character(len=14) :: 'height', 'vs', &
            'vs_base']
        character(len=14), parameter :: eql_keys(2) = [character(len=14) :: &
            'ref_strain_pct', 'max_iter']
        integer :: i, st

        where = located(path, gs)
        errmsg = ''
        do i = 1, size(required)
            if (.not. given(gs, trim(required(i)))) then
                errmsg = where//trim(required(i))//': missing (&slope needs height (m), vs ' &
                         //'and vs_base (m/s): the sliding mass and the ground below the ' &
                         //'slip surface)'
                return
            end if
        end do
        mass%soil = flexible_soil_code(trim(lower(adjustl(soil))))
        if (mass%soil == 0) then
            errmsg = where//'soil = '''//trim(soil)//''': unknown soil model (allowed: ' &
                     //flexible_soil_name(SOIL_LINEAR)//', ' &
                     //flexible_soil_name(SOIL_EQUIVALENT_LINEAR)//')'
            return
        end if
        mass%height = height
        mass%vs = vs
        mass%vs_base = vs_base
        mass%damping = damping
        mass%ref_strain_pct = ref_strain_pct
        mass%max_iter = max_iter
        msg = ''
        call flexible_mass_validate(mass, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            ! the library's message names the parameter, which is the key
            errmsg = where//trim(msg)
            return
        end if
        if (mass%soil == SOIL_LINEAR) then
            do i = 1, size(eql_keys)
                if (given(gs, trim(eql_keys(i)))) write(error_unit, '(a)') 'warning: ' &
                    //where//trim(eql_keys(i))//': not used with soil = ''linear'''
            end do
        end if
    end subroutine check_slope

    !> &slope as read back by the driver.
    subroutine echo_slope(mass)
        type(flexible_mass_t), intent(in) :: mass
        real(dp) :: height, vs, vs_base, damping, ref_strain_pct
        character(len=17) :: soil
        integer :: max_iter
        namelist /slope/ height, vs, vs_base, damping, soil, ref_strain_pct, max_iter
        height = mass%height
        vs = mass%vs
        vs_base = mass%vs_base
        damping = mass%damping
        soil = flexible_soil_name(mass%soil)
        ref_strain_pct = mass%ref_strain_pct
        max_iter = mass%max_iter
        write(echo_unit(), nml=slope)
    end subroutine echo_slope

    !> "sliding mass: height = 50 m, vs = 600 m/s, ..." (a header line of the table).
    function slope_line(mass) result(line)
        type(flexible_mass_t), intent(in) :: mass
        character(len=:), allocatable :: line
        line = 'sliding mass: height = '//shortest_str(mass%height)//' m, vs = ' &
            //shortest_str(mass%vs) &
               //' m/s, vs_base = '//shortest_str(mass%vs_base)//' m/s, damping = ' &
               //shortest_str(mass%damping)//', soil = '//flexible_soil_name(mass%soil)
        if (mass%soil == SOIL_EQUIVALENT_LINEAR) line = line//', ref_strain_pct = ' &
            //shortest_str(mass%ref_strain_pct)//' %, max_iter = '//int_str(mass%max_iter)
    end function slope_line

end module driver_slope
