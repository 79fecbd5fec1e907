!> What the analyses of the linear oscillator ('sdof', 'sdof_beta', 'sdof_shock') share:
!> the limits of their lists and the damping ratios of a `damping` key.
module driver_sdof_common
    use seispulse, only: dp, outside
    use driver_namelist_scan, only: nml_group
    use driver_input, only: given, list_length, value_name, num
    implicit none
    private

    public :: max_periods, max_dampings, check_dampings

    !> Most periods (list or range), most damping ratios.
    integer, parameter :: max_periods = 1000, max_dampings = 100
    !> Damping ratio when none is given.
    real(dp), parameter :: default_damping = 0.05_dp

contains

    !> The damping ratios of a `damping` list (default_damping when not given): each
    !> finite, in [0, 1). errmsg (without the location) on failure.
    subroutine check_dampings(group, list, values, errmsg)
        type(nml_group), intent(in) :: group
        real(dp), intent(in) :: list(:)
        real(dp), allocatable, intent(out) :: values(:)
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: n, i
        errmsg = ''
        if (.not. given(group, 'damping')) then
            values = [default_damping]
            return
        end if
        call list_length(list, 'damping', n, errmsg)
        if (len(errmsg) > 0) return
        do i = 1, n
            if (outside(list(i), 0.0_dp, 1.0_dp, .false., .true.)) then
                errmsg = value_name('damping', i, n)//' = '//num(list(i))//': must be a ' &
                         //'damping ratio in [0, 1)'
                return
            end if
        end do
        values = list(1:n)
    end subroutine check_dampings

end module driver_sdof_common
