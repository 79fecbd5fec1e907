!> Decoupled and coupled Newmark analyses of a flexible sliding mass on a record
!> (doc/flexible.md): the mass of seispulse_flexible_model (one shear-beam mode, radiation
!> damping, linear or equivalent-linear soil) slides on its base when its equivalent
!> acceleration exceeds the yield.
!>
!>  - decoupled: the modal response of the mass on a fixed base gives the history of the
!>    horizontal equivalent acceleration HEA = a + (2/pi) u'' (g) (doc/flexible.md (F.8));
!>    a rigid block driven by HEA slides downslope (or two ways, exact rule only).
!>  - coupled [RB99]: the sliding and the modal response are solved together; while
!>    sliding, the base of the mass carries the yield force (doc/flexible.md (F.10)-(F.14)).
!>
!> Two rules (the `method` argument):
!>  - FLEX_SLAMMER: SLAMMER 1.1 [SL13] step for step, in its own units (cm, cm/s^2 with
!>    g_cm = 100 g): incremental Newmark average acceleration from rest with the first sample
!>    as the first load increment, the decoupled slide integrated exactly for HEA linear
!>    over each step with the step that ends a slide discarded, the coupled stop sub-step,
!>    and SLAMMER's stepwise yield table (doc/flexible.md section 4, (F.24)-(F.29)).
!>  - FLEX_EXACT: the exact response to the piecewise-linear record (doc/flexible.md
!>    sections 5-7, module seispulse_flexible_exact).
!>
!> Sign: positive record acceleration drives downslope (positive) sliding in both
!> analyses. SLAMMER reaches the same by flipping the sign of its input inside the
!> decoupled analysis and not inside the coupled one; here the coupled rule runs on the
!> flipped record, as SLAMMER does, and its histories are turned back. kmax has the sign
!> of the HEA of the record as given in both analyses (SLAMMER's Coupled reports -kmax).
!>
!> Displacement: max_disp is the largest |s| over the run; SLAMMER publishes |s| at the end
!> of the record (|final_disp|). They differ only where SLAMMER's coupled trapezoid steps
!> back after an onset. SLAMMER's coupled arithmetic is used only for omega dt <= 10
!> (slammer_coupled_wdt_max); SLAMMER's decoupled arithmetic is stable at any omega dt.
module seispulse_flexible
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: positive, check_history_sizes
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_format, only: real_str, int_str
    use seispulse_pieces, only: record_step_check, g_product_max
    use seispulse_special, only: pi
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, &
                                 NEWMARK_DOWN, NEWMARK_ASYM, NEWMARK_EXACT
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t, modal_peak_t, &
                                        flexible_mass_validate, ky_table_validate, eql_iterate, &
                                        radiation_damping, participation_modal, &
                                        participation_total, modal_omega, modal_period, &
                                        FLEX_SLAMMER, FLEX_EXACT
    use seispulse_flexible_exact, only: modal_response_exact, modal_hea_extended, coupled_exact
    implicit none
    private

    public :: flexible_decoupled, flexible_coupled

    !> Newmark's average-acceleration parameters (doc/flexible.md (F.24), [C12])
    real(dp), parameter :: beta = 0.25_dp, gamma = 0.5_dp
    !> Largest omega dt (final properties) of SLAMMER's coupled arithmetic: above about 12
    !> its stick/slip switching with u'' from equilibrium turns the average-acceleration
    !> ringing of u'' into spurious slides (doc/flexible.md section 4, "Range")
    real(dp), parameter :: slammer_coupled_wdt_max = 10.0_dp
    !> Range of omega (rad/s) and smallest dt (s) accepted: the terms of k-hat (F.24) stay
    !> below 1e301, so no product of the response's coefficients overflows
    real(dp), parameter :: omega_min = 1.0e-150_dp, omega_max = 1.0e150_dp, dt_min = 1.0e-150_dp

    !> SLAMMER's modal response as the equivalent-linear iteration sees it: the record
    !> (g, pointing to the caller's array for the duration of the analysis) and its units.
    type, extends(modal_peak_t) :: slammer_peak_t
        real(dp), pointer :: accel(:) => null()  !! record (g)
        real(dp) :: gcm = 0.0_dp                 !! 100 g (cm/s^2 per g)
        real(dp) :: dt = 0.0_dp                  !! time step (s)
    contains
        procedure :: peak => slammer_peak
    end type slammer_peak_t

    !> The exact modal response as the equivalent-linear iteration sees it: the record
    !> (g, pointing to the caller's array during the analysis) and the work arrays of a pass.
    type, extends(modal_peak_t) :: exact_peak_t
        real(dp), pointer :: accel(:) => null()  !! record (g)
        real(dp) :: dt = 0.0_dp                  !! time step (s)
        real(dp) :: g = 0.0_dp                   !! gravity (m/s^2)
        real(dp), allocatable :: u(:)            !! modal displacement of a pass (m)
        real(dp), allocatable :: hea(:)          !! HEA of a pass (g)
    contains
        procedure :: peak => exact_peak
    end type exact_peak_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Decoupled analysis: the modal response on a fixed base, then a rigid block driven
    !> by its HEA (doc/flexible.md sections 1-4 and 6).
    !>
    !> accel(i) (g) at t = (i - 1) dt. Histories (optional, each of size(accel)): HEA (g),
    !> modal displacement u (m), sliding displacement s (m, >= 0 downslope for one-way) and
    !> velocity (m/s) at the samples. With a yield table (ky_disp, ky_values) `ky` is
    !> ignored and the mode must be down. Non-convergence of the equivalent-linear
    !> iteration: stat = SEISPULSE_NO_CONVERGENCE with res and the histories filled from the
    !> last iteration (res%converged = .false.).
    subroutine flexible_decoupled(accel, dt, ky, mass, method, g, res, stat, errmsg, &
                                  mode, ky_up, ky_disp, ky_values, hea, u_modal, s_hist, &
                                  sdot_hist)
        real(dp), intent(in) :: accel(:)                      !! record (g), finite
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        real(dp), intent(in) :: ky                            !! yield (g) > 0 (+inf: never)
        type(flexible_mass_t), intent(in) :: mass             !! the sliding mass
        integer, intent(in) :: method                         !! FLEX_SLAMMER or FLEX_EXACT
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        type(flexible_result_t), intent(out) :: res           !! the result
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: mode                 !! NEWMARK_DOWN (default), BOTH, ASYM
        !> upslope yield (g); required for NEWMARK_ASYM, unused otherwise
        real(dp), intent(in), optional :: ky_up
        !> yield table: displacement (m); with ky_values, or absent (ky used)
        real(dp), intent(in), optional :: ky_disp(:)
        !> yield table: yield (g); with ky_disp, or absent (ky used)
        real(dp), intent(in), optional :: ky_values(:)
        real(dp), intent(out), optional :: hea(:)             !! HEA at the samples (g)
        !> modal displacement u (m) relative to the base, the sign of (F.30): a > 0 drives u < 0
        real(dp), intent(out), optional :: u_modal(:)
        real(dp), intent(out), optional :: s_hist(:)          !! sliding displacement (m, > 0 down)
        real(dp), intent(out), optional :: sdot_hist(:)       !! sliding velocity (m/s, > 0 down)
        call flexible_run(.false., accel, dt, ky, mass, method, g, res, stat, errmsg, mode, &
                          ky_up, ky_disp, ky_values, hea, u_modal, s_hist, sdot_hist)
    end subroutine flexible_decoupled

    !> Coupled analysis [RB99]: sliding and modal response solved together (doc/flexible.md
    !> sections 1-4 and 7). Downslope sliding only. Arguments as flexible_decoupled; hea is
    !> the HEA of the decoupled response with the final properties (the one kmax comes from),
    !> u_modal the modal displacement of the coupled run.
    subroutine flexible_coupled(accel, dt, ky, mass, method, g, res, stat, errmsg, &
                                ky_disp, ky_values, hea, u_modal, s_hist, sdot_hist)
        real(dp), intent(in) :: accel(:)                      !! record (g), finite
        real(dp), intent(in) :: dt                            !! time step (s) > 0
        real(dp), intent(in) :: ky                            !! yield (g) > 0 (+inf: never)
        type(flexible_mass_t), intent(in) :: mass             !! the sliding mass
        integer, intent(in) :: method                         !! FLEX_SLAMMER or FLEX_EXACT
        real(dp), intent(in) :: g                             !! gravity (m/s^2) > 0
        type(flexible_result_t), intent(out) :: res           !! the result
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> yield table: displacement (m); with ky_values, or absent (ky used)
        real(dp), intent(in), optional :: ky_disp(:)
        !> yield table: yield (g); with ky_disp, or absent (ky used)
        real(dp), intent(in), optional :: ky_values(:)
        real(dp), intent(out), optional :: hea(:)             !! decoupled HEA (g)
        !> modal displacement u (m) relative to the base, the sign of (F.30): a > 0 drives u < 0
        real(dp), intent(out), optional :: u_modal(:)
        real(dp), intent(out), optional :: s_hist(:)          !! sliding displacement (m, > 0 down)
        real(dp), intent(out), optional :: sdot_hist(:)       !! sliding velocity (m/s, > 0 down)
        call flexible_run(.true., accel, dt, ky, mass, method, g, res, stat, errmsg, &
                          ky_disp=ky_disp, ky_values=ky_values, hea=hea, u_modal=u_modal, &
                          s_hist=s_hist, sdot_hist=sdot_hist)
    end subroutine flexible_coupled

    ! ------------------------------------------------------------------------------
    ! Checks and dispatch
    ! ------------------------------------------------------------------------------

    !> Both analyses: checks, the equivalent-linear iteration, the rule.
    subroutine flexible_run(coupled, accel, dt, ky, mass, method, g, res, stat, errmsg, &
                            mode, ky_up, ky_disp, ky_values, hea, u_modal, s_hist, sdot_hist)
        logical, intent(in) :: coupled
        real(dp), intent(in) :: accel(:), dt, ky, g
        type(flexible_mass_t), intent(in) :: mass
        integer, intent(in) :: method
        type(flexible_result_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer, intent(in), optional :: mode
        real(dp), intent(in), optional :: ky_up, ky_disp(:), ky_values(:)
        real(dp), intent(out), optional :: hea(:), u_modal(:), s_hist(:), sdot_hist(:)
        real(dp), allocatable :: tdisp(:), tky(:)
        integer :: mode_, eql_stat

        call flexible_mass_validate(mass, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (method /= FLEX_SLAMMER .and. method /= FLEX_EXACT) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'method: unknown code ' &
                           //'(allowed: 1 exact, 2 slammer)')
            return
        end if
        call record_step_check(accel, dt, g, stat, errmsg)   ! dt, g; not empty, finite
        if (stat /= SEISPULSE_SUCCESS) return
        mode_ = NEWMARK_DOWN
        if (present(mode)) mode_ = mode
        if (mode_ < NEWMARK_DOWN .or. mode_ > NEWMARK_ASYM) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode: unknown code ' &
                           //'(allowed: 1 down, 2 both, 3 asym)')
            return
        end if
        if (mode_ /= NEWMARK_DOWN .and. method /= FLEX_EXACT) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode: two-way sliding ' &
                           //'(both, asym) needs the exact rule (SLAMMER slides downslope only)')
            return
        end if
        if (mode_ == NEWMARK_ASYM) then
            if (.not. present(ky_up)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_up: required for ' &
                               //'mode asym (g, > 0; +inf: no upslope sliding)')
                return
            else if (.not. positive(ky_up)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_up = ' &
                               //real_str(ky_up)//': must be > 0 (g; +inf: no upslope sliding)')
                return
            end if
        end if
        if (present(ky_disp) .neqv. present(ky_values)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp, ky_values: give ' &
                           //'both (a yield table) or neither')
            return
        end if
        if (present(ky_disp)) then
            call ky_table_validate(ky_disp, ky_values, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (mode_ /= NEWMARK_DOWN) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'mode: a yield table ' &
                               //'(ky_disp, ky_values) is for downslope sliding only')
                return
            end if
            allocate(tdisp(size(ky_disp)), tky(size(ky_disp)))
            tdisp(:) = ky_disp
            tky(:) = ky_values
        else
            if (.not. positive(ky)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky = '//real_str(ky) &
                               //': must be > 0 (g; +inf: never slides)')
                return
            end if
            allocate(tdisp(1), tky(1))
            tdisp(1) = 0.0_dp
            tky(1) = ky
        end if
        call check_history_sizes(size(accel), [character(len=9) :: 'hea', 'u_modal', 's_hist', &
                                 'sdot_hist'], stat, errmsg, hea, u_modal, s_hist, sdot_hist)
        if (stat /= SEISPULSE_SUCCESS) return
        call response_checks(accel, dt, mass, method, g, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return

        if (method == FLEX_EXACT) then
            ! the analyses take an under-damped mass (total < 1; total >= 0 is checked by
            ! response_checks): the first pass takes damping + xi_f, the later ones
            ! xi_mat + xi_f <= (0.62 x 63.7 % + 1 %) + 0.2 < 0.61 (doc/flexible.md (F.16),
            ! (F.20)-(F.22)), so the first pass's total is the one to check
            if (.not. mass%damping + radiation_damping(mass%vs, mass%vs_base) < 1.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'damping = ' &
                               //real_str(mass%damping)//': with the radiation damping ' &
                               //real_str(radiation_damping(mass%vs, mass%vs_base)) &
                               //' the total must be < 1 for the exact rule')
                return
            end if
            call exact_run(coupled, accel, dt, tdisp, tky, mass, g, mode_, ky_up, &
                           present(ky_disp), res, eql_stat, stat, errmsg, hea, u_modal, &
                           s_hist, sdot_hist)
        else
            call slammer_run(coupled, accel, dt, tdisp, tky, mass, g, res, eql_stat, stat, &
                             errmsg, hea, u_modal, s_hist, sdot_hist)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. (ieee_is_finite(res%max_disp) .and. ieee_is_finite(res%kmax))) then
            call overflow_error(res, mass, stat, errmsg)
            return
        end if
        stat = eql_stat   ! SEISPULSE_NO_CONVERGENCE: errmsg already says so
    end subroutine flexible_run

    !> Checks of the response's inputs that name the real parameter: a total damping
    !> (user + radiation, the first equivalent-linear pass's) >= 0, dt >= dt_min, omega =
    !> pi vs/(2 H) in [omega_min, omega_max] (height, vs), and for the SLAMMER rule g_cm =
    !> 100 g and every accel(i) g_cm finite.
    subroutine response_checks(accel, dt, mass, method, g, stat, errmsg)
        real(dp), intent(in) :: accel(:), dt, g
        type(flexible_mass_t), intent(in) :: mass
        integer, intent(in) :: method
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp) :: xi_f, xi, a_max
        integer :: i
        stat = SEISPULSE_SUCCESS
        xi_f = radiation_damping(mass%vs, mass%vs_base)                      ! (F.16)
        xi = mass%damping + xi_f
        if (xi < 0.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'damping = ' &
                           //real_str(mass%damping)//': with the radiation damping xi_f = ' &
                           //real_str(xi_f)//' the total damping '//real_str(xi) &
                           //' must be >= 0 (damping >= -xi_f)')
            return
        end if
        if (dt < dt_min) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//real_str(dt) &
                           //': must be >= '//real_str(dt_min)//' (s)')
            return
        end if
        ! omega = pi vs/(2 H) in [omega_min, omega_max], compared without overflow  (F.2)
        if (mass%vs / omega_max > mass%height / (0.5_dp * pi) &
            .or. 0.5_dp * pi * mass%vs < omega_min * mass%height) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'height = ' &
                           //real_str(mass%height)//', vs = '//real_str(mass%vs) &
                           //': omega = pi vs/(2 height) must be in ['//real_str(omega_min) &
                           //', '//real_str(omega_max)//'] rad/s')
            return
        end if
        if (method /= FLEX_SLAMMER) return
        if (g > huge(g) / 100.0_dp) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//real_str(g) &
                           //': 100 g (cm/s^2 per g, SLAMMER''s unit) overflows')
            return
        end if
        a_max = g_product_max(100.0_dp * g)
        do i = 1, size(accel)
            if (abs(accel(i)) > a_max) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel('//int_str(i) &
                               //') = '//real_str(accel(i))//': accel 100 g (cm/s^2) ' &
                               //'overflows (g = '//real_str(g)//' m/s^2)')
                return
            end if
        end do
    end subroutine response_checks

    !> The response of valid input that still overflows (no one parameter to blame).
    subroutine overflow_error(res, mass, stat, errmsg)
        type(flexible_result_t), intent(in) :: res
        type(flexible_mass_t), intent(in) :: mass
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'the response overflows ' &
                       //'(omega = '//real_str(modal_omega(res%vs_final, mass%height)) &
                       //' rad/s, total damping '//real_str(res%damping_final)//')')
    end subroutine overflow_error

    ! ------------------------------------------------------------------------------
    ! The exact rule (doc/flexible.md sections 5-7, module seispulse_flexible_exact)
    ! ------------------------------------------------------------------------------

    !> FLEX_EXACT. The equivalent-linear iteration on the exact modal response, then the
    !> rigid block on the exact HEA (newmark_rigid, exact rule: mode, ky_up and the table
    !> interpolated linearly) or the exact coupled analysis (coupled_exact).
    subroutine exact_run(coupled, accel, dt, tdisp, tky, mass, g, mode, ky_up, table, res, &
                         eql_stat, stat, errmsg, hea, u_modal, s_hist, sdot_hist)
        logical, intent(in) :: coupled
        real(dp), intent(in), target :: accel(:)
        real(dp), intent(in) :: dt, tdisp(:), tky(:), g
        type(flexible_mass_t), intent(in) :: mass
        integer, intent(in) :: mode
        real(dp), intent(in), optional :: ky_up
        logical, intent(in) :: table
        type(flexible_result_t), intent(inout) :: res
        integer, intent(out) :: eql_stat, stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(out), optional :: hea(:), u_modal(:), s_hist(:), sdot_hist(:)
        type(exact_peak_t) :: resp
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: rres
        real(dp) :: omega, xi, kylo
        real(dp), allocatable :: hext(:), sh(:), wh(:)
        integer :: ntail, round

        resp%accel => accel
        resp%dt = dt
        resp%g = g
        allocate(resp%u(size(accel)), resp%hea(size(accel)))
        call eql_iterate(mass, resp, res%vs_final, res%damping_final, res%damping_radiation, &
                         res%iterations, res%converged, eql_stat, errmsg)
        nullify(resp%accel)
        stat = eql_stat
        if (eql_stat /= SEISPULSE_SUCCESS .and. eql_stat /= SEISPULSE_NO_CONVERGENCE) return
        xi = res%damping_final
        omega = modal_omega(res%vs_final, mass%height)
        res%period = modal_period(res%vs_final, mass%height)

        ! the final decoupled response: HEA and kmax (both analyses)
        call modal_response_exact(accel, dt, g, omega, xi, resp%u, resp%hea, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. all(ieee_is_finite(resp%hea))) then
            call overflow_error(res, mass, stat, errmsg)
            return
        end if
        res%kmax = signed_peak(resp%hea)
        if (present(hea)) hea(:) = resp%hea
        if (.not. coupled) then
            if (present(u_modal)) u_modal(:) = resp%u
            blk%mode = mode
            blk%ky = tky(1)
            if (present(ky_up)) blk%ky_up = ky_up
            if (table) then
                allocate(blk%ky_disp, source=tdisp)
                allocate(blk%ky_values, source=tky)
            end if
            ! the HEA goes on after the record (the beam's free vibration) until no slide can
            ! start and the block is at rest (doc/flexible.md (F.48))
            kylo = minval(tky)
            if (mode == NEWMARK_ASYM) kylo = min(kylo, ky_up)
            ntail = 0
            do round = 1, 65
                if (round > 64) then
                    call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky: the block ' &
                                   //'still slides long after the record')
                    return
                end if
                call modal_hea_extended(accel, dt, g, omega, xi, kylo, ntail, hext, stat, &
                                        errmsg)
                if (stat /= SEISPULSE_SUCCESS) return
                if (allocated(sh)) deallocate(sh, wh)
                allocate(sh(size(hext)), wh(size(hext)))
                call newmark_rigid(hext, dt, blk, NEWMARK_EXACT, g, rres, stat, errmsg, &
                                   u_hist=sh, w_hist=wh)
                if (stat /= SEISPULSE_SUCCESS) return
                if (rres%t_end <= real(size(hext) - 1, dp) * dt) exit
                ! still sliding at the end of the tail: a longer tail
                ntail = 2 * (size(hext) - size(accel)) &
                        + ceiling((rres%t_end - real(size(hext) - 1, dp) * dt) / dt)
            end do
            if (present(s_hist)) s_hist(:) = sh(1:size(accel))
            if (present(sdot_hist)) sdot_hist(:) = wh(1:size(accel))
            res%max_disp = rres%max_disp
            res%final_disp = rres%final_disp
            res%t_end = rres%t_end
        else if (table) then
            call coupled_exact(accel, dt, g, omega, xi, tky(1), res%max_disp, res%final_disp, &
                               res%t_end, stat, errmsg, ky_disp=tdisp, ky_values=tky, &
                               s_hist=s_hist, sdot_hist=sdot_hist, u_modal=u_modal)
        else
            call coupled_exact(accel, dt, g, omega, xi, tky(1), res%max_disp, res%final_disp, &
                               res%t_end, stat, errmsg, s_hist=s_hist, sdot_hist=sdot_hist, &
                               u_modal=u_modal)
        end if
    end subroutine exact_run

    !> max |u| (m) at the samples of the exact modal response for (omega, xi): O(n).
    subroutine exact_peak(self, omega, xi, u_peak, stat, errmsg)
        class(exact_peak_t), intent(inout) :: self
        real(dp), intent(in) :: omega, xi
        real(dp), intent(out) :: u_peak
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        u_peak = 0.0_dp
        call modal_response_exact(self%accel, self%dt, self%g, omega, xi, self%u, self%hea, &
                                  stat, errmsg)
        if (stat == SEISPULSE_SUCCESS) u_peak = maxval(abs(self%u))
    end subroutine exact_peak

    ! ------------------------------------------------------------------------------
    ! SLAMMER 1.1's arithmetic (doc/flexible.md section 4)
    ! ------------------------------------------------------------------------------

    !> FLEX_SLAMMER. Both analyses in SLAMMER's units. eql_stat receives the status of the
    !> equivalent-linear iteration (SEISPULSE_NO_CONVERGENCE is not an error here). The
    !> histories are filled in SLAMMER's units, then converted in place.
    subroutine slammer_run(coupled, accel, dt, tdisp, tky, mass, g, res, eql_stat, stat, &
                           errmsg, hea, u_modal, s_hist, sdot_hist)
        logical, intent(in) :: coupled
        real(dp), intent(in), target :: accel(:)
        real(dp), intent(in) :: dt, tdisp(:), tky(:), g
        type(flexible_mass_t), intent(in) :: mass
        type(flexible_result_t), intent(inout) :: res
        integer, intent(out) :: eql_stat, stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(out), optional :: hea(:), u_modal(:), s_hist(:), sdot_hist(:)
        type(slammer_peak_t) :: resp
        real(dp), allocatable :: avg(:)
        real(dp) :: gcm, omega, xi, u_peak, s_end

        gcm = 100.0_dp * g
        resp%accel => accel
        resp%gcm = gcm
        resp%dt = dt
        call eql_iterate(mass, resp, res%vs_final, res%damping_final, res%damping_radiation, &
                         res%iterations, res%converged, eql_stat, errmsg)
        nullify(resp%accel)
        stat = eql_stat
        if (eql_stat /= SEISPULSE_SUCCESS .and. eql_stat /= SEISPULSE_NO_CONVERGENCE) return
        stat = SEISPULSE_SUCCESS
        xi = res%damping_final
        omega = modal_omega(res%vs_final, mass%height)
        res%period = modal_period(res%vs_final, mass%height)
        if (coupled .and. omega > slammer_coupled_wdt_max / dt) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'height = ' &
                           //real_str(mass%height)//': SLAMMER''s coupled arithmetic is ' &
                           //'unstable for omega dt = '//real_str(omega * min(dt, huge(dt) &
                           / omega))//' > ' &
                           //real_str(slammer_coupled_wdt_max)//' (T/dt < ' &
                           //real_str(2.0_dp * pi / slammer_coupled_wdt_max)//', vs = ' &
                           //real_str(res%vs_final)//' m/s); use method=''exact''')
            return
        end if

        ! the final decoupled response: HEA and kmax (both analyses)
        allocate(avg(size(accel)))
        if (present(u_modal) .and. .not. coupled) then
            call slammer_response(accel, gcm, dt, omega, xi, u_peak, avg, u_modal)
            u_modal(:) = u_modal / 100.0_dp
        else
            call slammer_response(accel, gcm, dt, omega, xi, u_peak, avg)
        end if
        res%kmax = signed_peak(avg) / gcm
        if (present(hea)) hea(:) = avg / gcm

        if (.not. coupled) then
            call slammer_slide(avg, dt, 100.0_dp * tdisp, tky * gcm, res%max_disp, s_end, &
                               res%t_end, s_hist, sdot_hist)
            if (present(sdot_hist)) sdot_hist(:) = -sdot_hist / 100.0_dp   ! SLAMMER: s' < 0
        else
            ! SLAMMER's coupled input is the record times -1 (normal polarity)
            call slammer_coupled(accel, gcm, dt, omega, xi, 100.0_dp * tdisp, tky * gcm, &
                                 res%max_disp, s_end, res%t_end, s_hist, sdot_hist, u_modal)
            if (present(u_modal)) u_modal(:) = -u_modal / 100.0_dp
            if (present(sdot_hist)) sdot_hist(:) = sdot_hist / 100.0_dp
        end if
        if (present(s_hist)) s_hist(:) = s_hist / 100.0_dp
        res%max_disp = res%max_disp / 100.0_dp
        res%final_disp = s_end / 100.0_dp
    end subroutine slammer_run

    !> max |u| (m) of SLAMMER's modal response for (omega, xi): one pass, O(n), no storage.
    subroutine slammer_peak(self, omega, xi, u_peak, stat, errmsg)
        class(slammer_peak_t), intent(inout) :: self
        real(dp), intent(in) :: omega, xi
        real(dp), intent(out) :: u_peak
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        stat = SEISPULSE_SUCCESS
        if (present(errmsg)) continue
        call slammer_response(self%accel, self%gcm, self%dt, omega, xi, u_peak)
        u_peak = u_peak / 100.0_dp
    end subroutine slammer_peak

    !> SLAMMER's modal response (doc/flexible.md (F.24)-(F.26)): incremental Newmark
    !> average acceleration on u'' + 2 xi omega u' + omega^2 u = -(L/M) a; the first step
    !> from rest with the load increment a(1) and u'' from equilibrium; HEA = a + (L/Mtot) u''.
    !> The record is taken to cm/s^2 sample by sample (a = accel gcm).
    pure subroutine slammer_response(accel, gcm, dt, omega, xi, u_peak, avg, u)
        real(dp), intent(in) :: accel(:)             !! record (g)
        real(dp), intent(in) :: gcm                  !! 100 g (cm/s^2 per g)
        real(dp), intent(in) :: dt                   !! s
        real(dp), intent(in) :: omega                !! rad/s
        real(dp), intent(in) :: xi                   !! total damping (fraction)
        real(dp), intent(out) :: u_peak              !! max |u| (cm)
        real(dp), intent(out), optional :: avg(:)    !! HEA (cm/s^2)
        real(dp), intent(out), optional :: u(:)      !! modal displacement (cm)
        real(dp) :: khat, a, b, dp_, du, dv, dw, u1, v1, w1, acc1, acc2
        integer :: j
        khat = omega * omega + 2.0_dp * xi * omega * gamma / (beta * dt) &             ! (F.24)
               + 1.0_dp / (beta * (dt * dt))
        a = 1.0_dp / (beta * dt) + 2.0_dp * xi * omega * gamma / beta
        b = 1.0_dp / (2.0_dp * beta) + dt * 2.0_dp * xi * omega * (gamma / (2.0_dp * beta) &
                                                                   - 1.0_dp)
        ! first step from rest, load increment acc(1)                                   (F.26)
        acc2 = accel(1) * gcm
        du = -participation_modal * acc2 / khat
        u1 = du
        v1 = gamma / (beta * dt) * du
        w1 = -participation_modal * acc2 - 2.0_dp * xi * omega * v1 - omega * omega * u1
        u_peak = abs(u1)
        if (present(u)) u(1) = u1
        if (present(avg)) avg(1) = acc2 + participation_total * w1
        do j = 2, size(accel)
            acc1 = acc2
            acc2 = accel(j) * gcm
            dp_ = -participation_modal * (acc2 - acc1) + a * v1 + b * w1                 ! (F.25)
            du = dp_ / khat
            dv = gamma / (beta * dt) * du - gamma / beta * v1 &
                 + dt * (1.0_dp - gamma / (2.0_dp * beta)) * w1
            dw = 1.0_dp / (beta * (dt * dt)) * du - 1.0_dp / (beta * dt) * v1 - 0.5_dp / beta * w1
            u1 = u1 + du
            v1 = v1 + dv
            w1 = w1 + dw
            u_peak = max(u_peak, abs(u1))
            if (present(u)) u(j) = u1
            if (present(avg)) avg(j) = acc2 + participation_total * w1                 ! (F.8)
        end do
    end subroutine slammer_response

    !> SLAMMER's decoupled slide (Decoupled.d_sliding, doc/flexible.md (F.27)) with
    !> its stepwise table (F.29). With e = ky g - HEA(j-1), dH = HEA(j) - HEA(j-1), while
    !> sliding: s'(j) = s'(j-1) + e dt - dH dt/2, s(j) = s(j-1) - s'(j-1) dt - e dt^2/2
    !> + dH dt^2/6 (s' < 0 while sliding). A slide starts at the end of a step where
    !> HEA > ky g; on the step where s' >= 0 it stops and that step is discarded.
    pure subroutine slammer_slide(avg, dt, tdisp, tmug, s_max, s_end, t_end, s, sd)
        real(dp), intent(in) :: avg(:)     !! HEA (cm/s^2)
        real(dp), intent(in) :: dt         !! s
        real(dp), intent(in) :: tdisp(:)   !! table: displacement (cm), tdisp(1) = 0
        real(dp), intent(in) :: tmug(:)    !! table: ky g (cm/s^2)
        real(dp), intent(out) :: s_max     !! max |s| (cm)
        real(dp), intent(out) :: s_end     !! s at the last sample (cm)
        real(dp), intent(out) :: t_end     !! end of the last slide (s)
        real(dp), intent(out), optional :: s(:)    !! sliding displacement (cm), >= 0
        real(dp), intent(out), optional :: sd(:)   !! SLAMMER's s' (cm/s), <= 0 while sliding
        real(dp) :: e, dacc, sj, sdj, s1, sd1, avg_prev
        integer :: j, qq, n
        logical :: slide
        n = size(avg)
        qq = 1
        slide = .false.
        s1 = 0.0_dp
        sd1 = 0.0_dp
        s_max = 0.0_dp
        t_end = 0.0_dp
        avg_prev = 0.0_dp
        do j = 1, n
            if (j == 1) then
                sdj = 0.0_dp
                sj = 0.0_dp
            else if (.not. slide) then
                sdj = 0.0_dp
                sj = s1
            else
                dacc = avg(j) - avg_prev
                e = tmug(qq) - avg_prev
                sdj = sd1 + e * dt - 0.5_dp * dacc * dt                                   ! (F.27)
                sj = s1 - sd1 * dt - 0.5_dp * dt * dt * e + dacc * dt * dt / 6.0_dp       ! (F.27)
            end if
            if (.not. slide) then
                if (avg(j) > tmug(qq)) slide = .true.
            else if (sdj >= 0.0_dp) then
                ! end of the slide: this step is discarded (doc/flexible.md section 4)
                slide = .false.
                sj = s1
                sdj = 0.0_dp
                t_end = real(j - 1, dp) * dt
            end if
            call next_row(slide, sj, tdisp, qq)
            if (present(s)) s(j) = sj
            if (present(sd)) sd(j) = sdj
            s1 = sj
            sd1 = sdj
            s_max = max(s_max, abs(sj))
            avg_prev = avg(j)
        end do
        if (slide) t_end = real(n - 1, dp) * dt
        s_end = s1
    end subroutine slammer_slide

    !> SLAMMER's coupled analysis (Coupled, doc/flexible.md (F.10)-(F.14), (F.28)) on its
    !> input acc = -record (cm/s^2; SLAMMER flips the record of normal polarity here).
    !> Sticking: the modal equation under acc; sliding: under the yield load -ky g with the
    !> reduced mass d1 = 1 - L^2/(M Mtot); the base force per
    !> unit mass -acc - (L/Mtot) u'' starts a slide when it exceeds ky g; s'' = -acc - ky g
    !> - (L/Mtot) u'' integrated by the trapezoidal rule; when s' <= 0 the stop sub-step.
    subroutine slammer_coupled(accel, gcm, dt, omega, xi, tdisp, tmug, s_max, s_end, t_end, &
                               s, sd, u_out)
        real(dp), intent(in) :: accel(:)   !! record (g); SLAMMER's input is -accel gcm (cm/s^2)
        real(dp), intent(in) :: gcm        !! 100 g (cm/s^2 per g)
        real(dp), intent(in) :: dt         !! s
        real(dp), intent(in) :: omega      !! rad/s
        real(dp), intent(in) :: xi         !! total damping (fraction)
        real(dp), intent(in) :: tdisp(:)   !! table: displacement (cm), tdisp(1) = 0
        real(dp), intent(in) :: tmug(:)    !! table: ky g (cm/s^2)
        real(dp), intent(out) :: s_max     !! max |s| (cm)
        real(dp), intent(out) :: s_end     !! s at the last sample (cm)
        real(dp), intent(out) :: t_end     !! end of the last slide (s)
        real(dp), intent(out), optional :: s(:)      !! sliding displacement (cm), >= 0 downslope
        real(dp), intent(out), optional :: sd(:)     !! sliding velocity (cm/s)
        real(dp), intent(out), optional :: u_out(:)  !! modal displacement (cm), SLAMMER's sign
        real(dp) :: d1s, kh(2), ka(2), kb(2), d1(2)
        real(dp) :: u1, v1, w1, u2, v2, w2, s1, sd1, sdd1, s2, sd2, sdd2
        real(dp) :: acc11, acc22, deltp, du, dv, basef, mug, a_prev, a_j
        integer :: j, n, qq, k
        logical :: slide

        n = size(accel)
        ! coefficients: k = 1 sticking (d1 = 1), k = 2 sliding (d1 = 1 - L^2/(M Mtot))  (F.11)
        d1s = 1.0_dp - participation_modal * participation_total
        d1 = [1.0_dp, d1s]
        do k = 1, 2
            kh(k) = omega * omega + 2.0_dp * xi * omega * gamma / (beta * dt) &
                    + d1(k) / (beta * (dt * dt))
            ka(k) = d1(k) / (beta * dt) + 2.0_dp * xi * omega * gamma / beta
            kb(k) = d1(k) / (2.0_dp * beta) + dt * 2.0_dp * xi * omega &
                    * (gamma / (2.0_dp * beta) - 1.0_dp)
        end do
        qq = 1
        slide = .false.
        u2 = 0.0_dp
        v2 = 0.0_dp
        w2 = 0.0_dp
        s2 = 0.0_dp
        sd2 = 0.0_dp
        sdd2 = 0.0_dp
        s_max = 0.0_dp
        t_end = 0.0_dp
        a_prev = 0.0_dp
        do j = 1, n
            ! state of the previous step
            u1 = u2
            v1 = v2
            w1 = w2
            s1 = s2
            sd1 = sd2
            sdd1 = sdd2
            mug = tmug(qq)
            a_j = -(accel(j) * gcm)
            ! load of the modal equation (F.10)
            if (j == 1) then
                acc11 = 0.0_dp
                acc22 = a_j
            else if (.not. slide) then
                acc11 = a_prev
                acc22 = a_j
            else
                acc11 = -mug
                acc22 = -mug
            end if
            k = 1
            if (slide) k = 2
            deltp = -participation_modal * (acc22 - acc11)
            if (j > 1) deltp = deltp + ka(k) * v1 + kb(k) * w1
            du = deltp / kh(k)
            dv = gamma / (beta * dt) * du
            if (j > 1) dv = dv - gamma / beta * v1 + dt * (1.0_dp - gamma / (2.0_dp * beta)) * w1
            u2 = u1 + du
            v2 = v1 + dv
            w2 = (-participation_modal * acc22 - 2.0_dp * xi * omega * v2 &
                  - omega * omega * u2) / d1(k)
            ! sliding acceleration and base force per unit mass (F.13), (F.12)
            if (slide) sdd2 = -a_j - mug - participation_total * w2
            basef = -a_j - participation_total * w2
            if (slide) then
                sd2 = sd1 + 0.5_dp * dt * (sdd2 + sdd1)
                s2 = s1 + 0.5_dp * dt * (sd2 + sd1)
            end if
            if (.not. slide) then
                if (basef > mug) slide = .true.
            else if (sd2 <= 0.0_dp) then
                call slide_stop()
                slide = .false.
                sd2 = 0.0_dp
                sdd2 = 0.0_dp
            end if
            call next_row(slide, s2, tdisp, qq)
            if (present(s)) s(j) = s2
            if (present(sd)) sd(j) = sd2
            if (present(u_out)) u_out(j) = u2
            s_max = max(s_max, abs(s2))
            a_prev = a_j
        end do
        if (slide) t_end = real(n - 1, dp) * dt
        s_end = s2

    contains

        !> SLAMMER's slidestop (F.28): the stop at the fraction dd = -s'1/(s'2 - s'1) of the
        !> step; the sliding solution at the step's end is kept as the state at the stop
        !> (SLAMMER re-solves the same step), s', s re-integrated over dd dt, then a sticking
        !> sub-step of (1 - dd) dt in SLAMMER's own k-hat, a, b form. dd = 0 (s'1 = 0, the
        !> step after an onset): nothing is redone.
        subroutine slide_stop()
            real(dp) :: dd, ddt, acc1b, khat, a, b
            t_end = real(j - 2, dp) * dt
            if (.not. (sd1 > 0.0_dp)) return   ! s'1 >= 0 while sliding
            dd = -sd1 / (sd2 - sd1)
            ddt = dd * dt
            t_end = t_end + ddt
            acc1b = a_prev + dd * (a_j - a_prev)
            u1 = u2
            v1 = v2
            w1 = w2
            sdd2 = -acc1b - mug - participation_total * w2
            sd2 = sd1 + 0.5_dp * ddt * (sdd2 + sdd1)
            s2 = s1 + 0.5_dp * ddt * (sd1 + sd2)
            ! sticking for the rest of the step, load from -ky g to acc(j)
            ddt = (1.0_dp - dd) * dt
            khat = 1.0_dp + 2.0_dp * xi * omega * gamma * ddt + omega * omega * beta * (ddt * ddt)
            a = d1s + 2.0_dp * xi * omega * ddt * (gamma - 1.0_dp) &
                + omega * omega * (ddt * ddt) * (beta - 0.5_dp)
            b = omega * omega * ddt
            deltp = -participation_modal * (a_j + mug) + a * w1 - b * v1
            w2 = deltp / khat
            v2 = v1 + (1.0_dp - gamma) * ddt * w1 + gamma * ddt * w2
            u2 = u1 + v1 * ddt + (0.5_dp - beta) * (ddt * ddt) * w1 + beta * (ddt * ddt) * w2
        end subroutine slide_stop

    end subroutine slammer_coupled

    !> SLAMMER's residual_mu (doc/flexible.md (F.29)): at rest with |s| >= the current row's
    !> displacement, the next row of the table takes over (one row per step). Row 1 has
    !> displacement 0, so row 2 applies from the first step at rest.
    pure subroutine next_row(slide, s, tdisp, qq)
        logical, intent(in) :: slide
        real(dp), intent(in) :: s, tdisp(:)
        integer, intent(inout) :: qq
        if (size(tdisp) > 1 .and. .not. slide) then
            if (abs(s) >= tdisp(qq) .and. qq < size(tdisp)) qq = qq + 1
        end if
    end subroutine next_row

    !> The value of largest |x| with its sign (SLAMMER's avg_acc: a tie goes to the
    !> positive value).
    pure real(dp) function signed_peak(x) result(peak)
        real(dp), intent(in) :: x(:)
        real(dp) :: hi, lo
        hi = max(maxval(x), 0.0_dp)
        lo = min(minval(x), 0.0_dp)
        if (-lo > hi) then
            peak = lo
        else
            peak = hi
        end if
    end function signed_peak

end module seispulse_flexible
