!> Flexible sliding masses (decoupled and coupled Newmark analyses): the model shared by
!> every integration rule (doc/flexible.md sections 1-3).
!>
!> The sliding mass is a uniform 1-D shear beam of height H on a rigid base, kept to its
!> fundamental mode (doc/flexible.md (F.1)-(F.8)): omega = pi Vs/(2 H), participation
!> L/M = 4/pi, L/Mtot = 2/pi. Its damping is the user's viscous damping plus the
!> radiation damping of Lee [L04] (F.15)-(F.16); an equivalent-linear soil [RB99] iterates Vs
!> and the material damping on the effective strain of the response (F.17)-(F.23) with the
!> hyperbolic modulus curve and the scaled Masing damping of Darendeli [D01]. The one
!> iteration routine, eql_iterate, serves every rule: the response is an object of a
!> type extending modal_peak_t (its `peak` binding returns max|u| for a frequency and a
!> damping), so the rules differ only in how they integrate the modal equation.
module seispulse_flexible_model
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive, outside
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_format, only: real_str, int_str, name_of, name_len, code_of
    use seispulse_special, only: log1p, pi
    implicit none
    private

    public :: SOIL_LINEAR, SOIL_EQUIVALENT_LINEAR, FLEX_SLAMMER, FLEX_EXACT
    public :: flexible_mass_t, flexible_result_t, modal_peak_t
    public :: flexible_mass_validate, radiation_damping, eql_properties, ky_table_validate, &
              eql_iterate, masing_damping_pct, flexible_soil_name, flexible_soil_code
    public :: participation_modal, participation_total, strain_factor, eql_tolerance_pct
    public :: modal_omega, modal_period, ky_table_at

    integer, parameter :: SOIL_LINEAR = 1             !! linear elastic sliding mass
    integer, parameter :: SOIL_EQUIVALENT_LINEAR = 2  !! equivalent-linear iteration (F.17)-(F.23)
    integer, parameter :: FLEX_EXACT = 1    !! exact piecewise-linear response (= NEWMARK_EXACT)
    integer, parameter :: FLEX_SLAMMER = 2  !! SLAMMER 1.1's arithmetic (= NEWMARK_SLAMMER)

    character(len=*), parameter :: soil_names(2) = [character(len=17) :: 'linear', &
                                                   'equivalent_linear']

    !> L/M of the fundamental shear-beam mode, 4/pi (F.5)
    real(dp), parameter :: participation_modal = 4.0_dp / pi
    !> L/Mtot, 2/pi (F.6)
    real(dp), parameter :: participation_total = 2.0_dp / pi
    !> effective strain per u/H: 0.65 (effective-strain ratio) x 1.57 (the mode's largest
    !> slope, pi/2 as SLAMMER writes it) (F.17)
    real(dp), parameter :: strain_factor = 0.65_dp * 1.57_dp
    !> convergence of the equivalent-linear iteration: both relative changes <= 5 % (F.23)
    real(dp), parameter :: eql_tolerance_pct = 5.0_dp
    !> below this strain ratio gamma/gamma_r the Masing damping is its series (F.20)
    real(dp), parameter :: masing_series_below = 0.1_dp
    !> largest strain ratio gamma_eff/gamma_r of the iteration: (F.20) stays finite (x^2)
    real(dp), parameter :: strain_ratio_max = 1.0e150_dp

    !> The flexible sliding mass (SI; damping as a fraction, the reference strain in percent).
    type :: flexible_mass_t
        real(dp) :: height = 0.0_dp          !! H (m) > 0
        real(dp) :: vs = 0.0_dp              !! shear-wave velocity of the sliding mass (m/s) > 0
        real(dp) :: vs_base = 0.0_dp         !! Vs below the slip surface (m/s) > 0
        !> user viscous damping (fraction), -0.5 <= d < 1; the analyses also need d + xi_f >= 0
        !> (and < 1 for the exact rule), xi_f the radiation damping
        real(dp) :: damping = 0.05_dp
        integer :: soil = SOIL_LINEAR        !! SOIL_LINEAR or SOIL_EQUIVALENT_LINEAR
        real(dp) :: ref_strain_pct = 0.05_dp !! reference strain (percent) > 0 (EQL only)
        integer :: max_iter = 100            !! equivalent-linear iteration cap >= 1
    end type flexible_mass_t

    !> Result of a decoupled or coupled analysis (SI).
    type :: flexible_result_t
        !> largest |s| over the run (m); SLAMMER publishes |final_disp|, which is smaller
        !> only where its coupled trapezoid steps back after an onset (doc/flexible.md
        !> section 4)
        real(dp) :: max_disp = 0.0_dp
        real(dp) :: final_disp = 0.0_dp      !! s at the end (m) (signed for two-way exact)
        !> signed HEA of largest |value| (g) of the final decoupled response to the record as
        !> given, both analyses (SLAMMER's Decoupled sign; its Coupled reports -kmax, its
        !> tables print |kmax|)
        real(dp) :: kmax = 0.0_dp
        real(dp) :: vs_final = 0.0_dp        !! Vs used for the final response (m/s)
        !> total damping used (fraction): material (or the user's) + radiation
        real(dp) :: damping_final = 0.0_dp
        real(dp) :: damping_radiation = 0.0_dp  !! radiation damping xi_f (fraction)
        real(dp) :: period = 0.0_dp          !! 4 H / Vs_final (s)
        integer :: iterations = 0            !! equivalent-linear iterations (0 for linear)
        logical :: converged = .true.        !! the equivalent-linear iteration converged
        real(dp) :: t_end = 0.0_dp           !! end of the last slide (s from the first sample)
    end type flexible_result_t

    !> A modal response of the sliding mass to a record, as the equivalent-linear
    !> iteration needs it: the largest |u| (m) of the modal displacement for a circular
    !> frequency omega (rad/s) and a total damping ratio xi. An integration rule extends
    !> this type with its record and work arrays.
    type, abstract :: modal_peak_t
    contains
        procedure(peak_iface), deferred :: peak
    end type modal_peak_t

    abstract interface
        !> max |u(t)| (m) of the modal response with (omega, xi); O(n).
        subroutine peak_iface(self, omega, xi, u_peak, stat, errmsg)
            import :: modal_peak_t, dp
            class(modal_peak_t), intent(inout) :: self  !! the modal response's data
            real(dp), intent(in) :: omega                        !! rad/s > 0
            real(dp), intent(in) :: xi                           !! total damping (fraction)
            real(dp), intent(out) :: u_peak                      !! max |u| (m)
            integer, intent(out) :: stat                         !! SEISPULSE_SUCCESS or code
            character(len=*), intent(inout), optional :: errmsg !! message when stat /= 0
        end subroutine peak_iface
    end interface

contains

    !> Check a sliding mass; the message names the offending parameter and its range.
    subroutine flexible_mass_validate(mass, stat, errmsg)
        type(flexible_mass_t), intent(in) :: mass             !! the sliding mass
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(mass%height)) then
            call bad('height = '//real_str(mass%height)//': must be a finite number > 0 (m)')
        else if (.not. finite_positive(mass%vs)) then
            call bad('vs = '//real_str(mass%vs)//': must be a finite number > 0 (m/s)')
        else if (.not. finite_positive(mass%vs_base)) then
            call bad('vs_base = '//real_str(mass%vs_base)//': must be a finite number > 0 (m/s)')
        else if (outside(mass%damping, -0.5_dp, 1.0_dp, .false., .true.)) then
            call bad('damping = '//real_str(mass%damping)//': must be in [-0.5, 1) (fraction)')
        else if (mass%soil /= SOIL_LINEAR .and. mass%soil /= SOIL_EQUIVALENT_LINEAR) then
            call bad('soil = '//int_str(mass%soil)//': unknown code (allowed: 1 linear, ' &
                     //'2 equivalent_linear)')
        else if (.not. finite_positive(mass%ref_strain_pct)) then
            call bad('ref_strain_pct = '//real_str(mass%ref_strain_pct) &
                     //': must be a finite number > 0 (percent)')
        else if (mass%max_iter < 1) then
            call bad('max_iter = '//int_str(mass%max_iter)//': must be >= 1')
        end if
    contains
        subroutine bad(message)
            character(len=*), intent(in) :: message
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, message)
        end subroutine bad
    end subroutine flexible_mass_validate

    !> Radiation ("impedance") damping of the sliding mass on its base, Lee [L04]
    !> (doc/flexible.md (F.16)): xi_f = min(0.2, 0.55016 (vs_base/vs)^-0.9904) (fraction).
    pure real(dp) function radiation_damping(vs, vs_base) result(xi_f)
        real(dp), intent(in) :: vs       !! Vs of the sliding mass (m/s) > 0
        real(dp), intent(in) :: vs_base  !! Vs below the slip surface (m/s) > 0
        xi_f = min(0.2_dp, 0.55016_dp * (vs_base / vs)**(-0.9904_dp))   ! (F.16)
    end function radiation_damping

    !> Masing damping of the hyperbolic curve (percent) at the strain ratio x = gamma/gamma_r
    !> >= 0 (doc/flexible.md (F.20)): (100/pi) [4 (1 + x)(x - ln(1 + x))/x^2 - 2]; below
    !> x = 0.1 its series (400/pi) sum_m (-1)^(m+1) x^m/((m+1)(m+2)), so that it tends to 0
    !> without cancellation.
    pure real(dp) function masing_damping_pct(x) result(d)
        real(dp), intent(in) :: x  !! gamma/gamma_r >= 0
        real(dp) :: term
        integer :: m
        if (x < masing_series_below) then
            ! x^m/((m+1)(m+2)) < 0.1^m: 18 terms reach 1e-18 of the first
            d = 0.0_dp
            term = 1.0_dp
            do m = 1, 18
                term = -term * x
                d = d - term / real((m + 1) * (m + 2), dp)
            end do
            d = 400.0_dp / pi * d
        else
            d = 100.0_dp / pi * (4.0_dp * ((x - log1p(x)) * (1.0_dp + x) / (x * x)) - 2.0_dp)
        end if
    end function masing_damping_pct

    !> Equivalent-linear soil properties at an effective strain (doc/flexible.md
    !> (F.18)-(F.21)): the hyperbolic modulus reduction G/Gmax = 1/(1 + gamma/gamma_r) and
    !> the material damping xi_mat = (0.62 (G/Gmax)^0.1 D_Masing + 1 %) as a fraction.
    pure subroutine eql_properties(gamma_eff_pct, ref_strain_pct, g_ratio, damping_material)
        real(dp), intent(in) :: gamma_eff_pct      !! effective shear strain (percent) >= 0
        real(dp), intent(in) :: ref_strain_pct     !! reference strain gamma_r (percent) > 0
        real(dp), intent(out) :: g_ratio           !! G/Gmax in (0, 1]
        real(dp), intent(out) :: damping_material  !! xi_mat (fraction)
        real(dp) :: x
        x = gamma_eff_pct / ref_strain_pct
        g_ratio = 1.0_dp / (1.0_dp + x)                                          ! (F.18)
        damping_material = (0.62_dp * g_ratio**0.1_dp * masing_damping_pct(x) &   ! (F.21)
                            + 1.0_dp) / 100.0_dp
    end subroutine eql_properties

    !> Check a yield table: ky_disp (m) finite, first 0, strictly increasing; ky_values (g)
    !> finite and > 0; the same size >= 1.
    subroutine ky_table_validate(ky_disp, ky_values, stat, errmsg)
        real(dp), intent(in) :: ky_disp(:)                    !! sliding displacement (m)
        real(dp), intent(in) :: ky_values(:)                  !! yield acceleration (g)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i
        stat = SEISPULSE_SUCCESS
        if (size(ky_disp) < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp: the table needs ' &
                           //'at least one row')
            return
        end if
        if (size(ky_values) /= size(ky_disp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_values: must have the ' &
                           //'size of ky_disp ('//int_str(size(ky_disp))//')')
            return
        end if
        if (abs(ky_disp(1)) > 0.0_dp .or. .not. ieee_is_finite(ky_disp(1))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp(1) = ' &
                           //real_str(ky_disp(1))//': must be 0 (m)')
            return
        end if
        do i = 2, size(ky_disp)
            if (.not. ieee_is_finite(ky_disp(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp('//int_str(i) &
                               //') = '//real_str(ky_disp(i))//': must be finite (m)')
                return
            else if (.not. ky_disp(i) > ky_disp(i - 1)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_disp('//int_str(i) &
                               //') = '//real_str(ky_disp(i))//': must be > ky_disp(' &
                               //int_str(i - 1)//') (strictly increasing, m)')
                return
            end if
        end do
        do i = 1, size(ky_values)
            if (.not. finite_positive(ky_values(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ky_values('//int_str(i) &
                               //') = '//real_str(ky_values(i))//': must be a finite number ' &
                               //'> 0 (g)')
                return
            end if
        end do
    end subroutine ky_table_validate

    !> ky (g) at the displacement x (m) of a checked table: linear on its segments, constant
    !> beyond the last row (doc/flexible.md section 6; doc/newmark.md section 5).
    pure real(dp) function ky_table_at(x, ky_disp, ky_values) result(ky)
        real(dp), intent(in) :: x              !! displacement (m)
        real(dp), intent(in) :: ky_disp(:)     !! table displacements (m), from 0, increasing
        real(dp), intent(in) :: ky_values(:)   !! table yields (g), same size
        integer :: j, nt
        nt = size(ky_disp)
        ky = ky_values(nt)
        do j = 1, nt - 1
            if (x < ky_disp(j + 1)) then
                ky = ky_values(j) + (ky_values(j + 1) - ky_values(j)) &
                     * ((x - ky_disp(j)) / (ky_disp(j + 1) - ky_disp(j)))
                return
            end if
        end do
    end function ky_table_at

    !> Circular frequency of the mass's first shear mode (rad/s), (F.2): pi Vs / (2 H).
    elemental real(dp) function modal_omega(vs, height)
        real(dp), intent(in) :: vs      !! shear-wave velocity (m/s)
        real(dp), intent(in) :: height  !! H (m)
        modal_omega = pi * vs / (2.0_dp * height)
    end function modal_omega

    !> Period of the mass's first shear mode (s), (F.2): 4 H / Vs.
    elemental real(dp) function modal_period(vs, height)
        real(dp), intent(in) :: vs      !! shear-wave velocity (m/s)
        real(dp), intent(in) :: height  !! H (m)
        modal_period = 4.0_dp * height / vs
    end function modal_period

    !> The equivalent-linear iteration (doc/flexible.md (F.17)-(F.23)), shared by every
    !> integration rule. From Vs0 = mass%vs and xi = mass%damping + xi_f(Vs0), each pass runs
    !> the response once (O(n)), takes gamma_eff = 0.65 x 1.57 max|u|/H, and sets
    !> Vs = Vs0 sqrt(G/Gmax), xi = xi_mat + xi_f(Vs) (the user's damping is dropped after the
    !> first pass). It stops when |dG/G| <= 5 % and |dxi_mat/xi_mat| <= 5 %, both measured
    !> against the previous pass; the previous material damping starts at 0 (SLAMMER's
    !> start), so there are at least two passes. At max_iter passes without convergence:
    !> stat = SEISPULSE_NO_CONVERGENCE, converged = .false., and vs, xi, xi_f hold the last
    !> pass's properties. For a linear mass: no pass, vs = Vs0.
    subroutine eql_iterate(mass, response, vs, xi, xi_f, iterations, converged, stat, errmsg)
        type(flexible_mass_t), intent(in) :: mass             !! the mass (validated)
        class(modal_peak_t), intent(inout) :: response        !! the modal response of a rule
        real(dp), intent(out) :: vs                           !! final Vs (m/s)
        real(dp), intent(out) :: xi                           !! final total damping (fraction)
        real(dp), intent(out) :: xi_f                         !! final radiation damping (fraction)
        integer, intent(out) :: iterations                    !! passes made (0: linear)
        logical, intent(out) :: converged                     !! both changes <= 5 %
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: u_peak, gamma_pct, g_ratio, d_mat, d_mat_prev, vs_new, dg_pct, dd_pct
        integer :: it

        stat = SEISPULSE_SUCCESS
        vs = mass%vs
        xi_f = radiation_damping(vs, mass%vs_base)
        xi = mass%damping + xi_f
        iterations = 0
        converged = .true.
        if (mass%soil /= SOIL_EQUIVALENT_LINEAR) return

        converged = .false.
        d_mat_prev = 0.0_dp
        do it = 1, mass%max_iter
            call response%peak(modal_omega(vs, mass%height), xi, u_peak, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            iterations = it
            gamma_pct = 100.0_dp * strain_factor * u_peak / mass%height          ! (F.17)
            if (.not. ieee_is_finite(gamma_pct)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'the response ' &
                               //'overflows (equivalent-linear pass '//int_str(it)//')')
                return
            else if (gamma_pct / strain_ratio_max > mass%ref_strain_pct) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ref_strain_pct = ' &
                               //real_str(mass%ref_strain_pct)//': the strain ratio ' &
                               //'gamma_eff/gamma_r = '//real_str(gamma_pct) &
                               //'/ref_strain_pct exceeds '//real_str(strain_ratio_max) &
                               //'; must be a larger reference strain (percent)')
                return
            end if
            call eql_properties(gamma_pct, mass%ref_strain_pct, g_ratio, d_mat)
            vs_new = mass%vs * sqrt(g_ratio)                                     ! (F.19)
            dg_pct = abs((vs * vs - vs_new * vs_new) / (vs * vs)) * 100.0_dp     ! (F.23)
            if (d_mat_prev > 0.0_dp) then
                dd_pct = abs((d_mat_prev - d_mat) / d_mat_prev) * 100.0_dp
            else
                dd_pct = huge(dd_pct)   ! SLAMMER's start: the previous damping is 0
            end if
            vs = vs_new
            xi_f = radiation_damping(vs, mass%vs_base)
            xi = d_mat + xi_f                                                    ! (F.22)
            d_mat_prev = d_mat
            if (dg_pct <= eql_tolerance_pct .and. dd_pct <= eql_tolerance_pct) then
                converged = .true.
                return
            end if
        end do
        call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, 'max_iter = ' &
                       //int_str(mass%max_iter)//': the equivalent-linear iteration did not ' &
                       //'converge (changes of G and damping still > 5 %); the results of ' &
                       //'the last iteration are kept (vs = '//real_str(vs)//' m/s)')
    end subroutine eql_iterate

    !> Name of a soil code ('linear', 'equivalent_linear'; '?' if unknown).
    pure function flexible_soil_name(code) result(name)
        integer, intent(in) :: code  !! SOIL_LINEAR or SOIL_EQUIVALENT_LINEAR
        character(len=name_len(code, soil_names)) :: name
        name = name_of(code, soil_names)
    end function flexible_soil_name

    !> Code of a soil name (0 if unknown).
    pure integer function flexible_soil_code(name)
        character(len=*), intent(in) :: name  !! 'linear' or 'equivalent_linear'
        flexible_soil_code = code_of(name, soil_names)
    end function flexible_soil_code

end module seispulse_flexible_model
