!> Thin f2py layer of seispulse_record_suite (EN 1998-1 3.2.3.1.2(4) record-suite check):
!> plain external subroutines, explicit-shape arrays, int flags, `stat` + `errmsg` out, no
!> numerics. The result type is flattened into `values` (reals) and `flags` (0/1).

!> The check from the records (ec8_suite_check_records): accel (g) the nr records
!> concatenated, first/npts/dt per record; the target: code 1 EC8 (spectrum_type, ag (g),
!> ground) or 2 EAK (alpha, ground, importance, eta_min, exponent). nmax from
!> sp_suite_records_room; margin < 0: the default. periods(1:n) the grid with the refined
!> minima; values = [t1, t_low, t_high, pga_mean, pga_target, pga_ratio, min_ratio,
!> t_min_ratio, common_scale, own_pga_ratio, own_min_ratio, own_t_min_ratio, grid_min_ratio,
!> grid_own_min_ratio]; flags = [pga_ok, spectrum_ok, count_ok, mean_allowed, passed,
!> own_passed] (1 = true); ints = [scale_rule, n_searched, bad_record, n_grid].
subroutine sp_ec8_suite_check_records(na, nr, ne, accel, first, npts, dt, code, spectrum_type, &
                                      ag, ground, alpha, importance, eta_min, exponent, t1, fit, &
                                      n_points, extra, min_records, margin, nmax, periods, n, &
                                      psa, pga, target_psa, mean, ratio, own_mean, own_scale, &
                                      values, flags, ints, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_record_suite, only: ec8_suite_check_records, suite_check_t, suite_target_t
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: na, nr, ne
    integer, intent(in) :: na, nr, ne, code, spectrum_type, ground, fit, n_points, min_records
    integer, intent(in) :: nmax, first(nr), npts(nr)
    real(dp), intent(in) :: accel(na), dt(nr), ag, alpha, importance, eta_min, exponent, t1
    real(dp), intent(in) :: extra(ne), margin
    real(dp), intent(out) :: periods(nmax), psa(nmax, nr), pga(nr), target_psa(nmax)
    real(dp), intent(out) :: mean(nmax), ratio(nmax), own_mean(nmax), own_scale(nr), values(14)
    integer, intent(out) :: n, flags(6), ints(4)
    integer, intent(out) :: stat
    character(len=512), intent(out) :: errmsg
    type(suite_check_t) :: c
    type(suite_target_t) :: tg
    errmsg = ''
    tg = suite_target_t(code=code, spectrum_type=spectrum_type, ag=ag, ground=ground, &
                        alpha=alpha, importance=importance, eta_min=eta_min, exponent=exponent)
    if (margin < 0.0_dp) then
        call ec8_suite_check_records(accel, first, npts, dt, tg, t1, fit, c, periods, n, psa, &
                                     pga, target_psa, mean, ratio, own_mean, own_scale, stat, &
                                     errmsg, n_points=n_points, extra=extra, &
                                     min_records=min_records, bad_record=ints(3))
    else
        call ec8_suite_check_records(accel, first, npts, dt, tg, t1, fit, c, periods, n, psa, &
                                     pga, target_psa, mean, ratio, own_mean, own_scale, stat, &
                                     errmsg, n_points=n_points, extra=extra, &
                                     min_records=min_records, bad_record=ints(3), margin=margin)
    end if
    values = [c%t1, c%t_low, c%t_high, c%pga_mean, c%pga_target, c%pga_ratio, c%min_ratio, &
              c%t_min_ratio, c%common_scale, c%own_pga_ratio, c%own_min_ratio, &
              c%own_t_min_ratio, c%grid_min_ratio, c%grid_own_min_ratio]
    flags = merge(1, 0, [c%pga_ok, c%spectrum_ok, c%count_ok, c%mean_allowed, c%passed, &
                         c%own_passed])
    ints(1:2) = [c%scale_rule, c%n_searched]
    ints(4) = c%n_grid
end subroutine sp_ec8_suite_check_records

!> Room (nmax) of the period arrays of sp_ec8_suite_check_records for n_points and ne extra
!> periods (suite_records_room).
subroutine sp_suite_records_room(n_points, ne, room)
    use seispulse_record_suite, only: suite_records_room
    implicit none
    !f2py threadsafe
    integer, intent(in) :: n_points, ne
    integer, intent(out) :: room
    room = suite_records_room(n_points, ne)
end subroutine sp_suite_records_room

!> The fraction of the target that rule (c) asks of the mean spectrum (-).
subroutine sp_suite_spectrum_fraction(fraction)
    use seispulse_kinds, only: dp
    use seispulse_record_suite, only: SUITE_SPECTRUM_FRACTION
    implicit none
    !f2py threadsafe
    real(dp), intent(out) :: fraction
    fraction = SUITE_SPECTRUM_FRACTION
end subroutine sp_suite_spectrum_fraction
