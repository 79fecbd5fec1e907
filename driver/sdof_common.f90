!> What the analyses of the linear oscillator ('sdof', 'sdof_beta', 'sdof_shock') share:
!> the limits of their lists and the checks of a list of values (damping ratios, gamma).
module driver_sdof_common
    use seispulse, only: dp, shortest_str, outside
    use driver_namelist_scan, only: nml_group
    use driver_input, only: given, list_length, value_name
    implicit none
    private

    public :: max_periods, max_dampings, check_dampings, check_list

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
        call check_list(group, 'damping', list, default_damping, 0.0_dp, 1.0_dp, .true., &
                        'a damping ratio in [0, 1)', values, errmsg)
    end subroutine check_dampings

    !> The values of a list key (`default` alone when it is not given): each in [lo, hi],
    !> hi itself excluded with `open_hi`. errmsg (without the location) on failure:
    !> "key(i) = x: must be <rule>".
    subroutine check_list(group, key, list, default, lo, hi, open_hi, rule, values, errmsg)
        type(nml_group), intent(in) :: group
        character(len=*), intent(in) :: key
        real(dp), intent(in) :: list(:)
        real(dp), intent(in) :: default, lo, hi
        logical, intent(in) :: open_hi
        character(len=*), intent(in) :: rule              !! what a value must be
        real(dp), allocatable, intent(out) :: values(:)
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: n, i
        errmsg = ''
        if (.not. given(group, key)) then
            values = [default]
            return
        end if
        call list_length(list, key, n, errmsg)
        if (len(errmsg) > 0) return
        do i = 1, n
            if (outside(list(i), lo, hi, .false., open_hi)) then
                errmsg = value_name(key, i, n)//' = '//shortest_str(list(i))//': must be '//rule
                return
            end if
        end do
        values = list(1:n)
    end subroutine check_list

end module driver_sdof_common
