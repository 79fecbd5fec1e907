!> Divided differences of exp (seispulse_divided_differences) against independent values:
!> mpmath at 600 digits (the quotient recursion on the exact double nodes, cross-checked
!> with the Taylor series sum_k h_k/(k + n)! at 200 digits; the series alone where nodes
!> repeat). Cases: repeated nodes (the limits e[x, x] = e^x, ...), clustered nodes where the
!> quotient cancels, nodes just either side of the series/recurrence switch, conjugate
!> pairs, complex zeros (e[2 pi i, 0] = 0), large |x|; symmetry in the nodes and conjugation.
module test_divided_differences
    use seispulse_kinds, only: dp
    use seispulse_special, only: pi
    use seispulse_divided_differences, only: exp_dd1, exp_dd2, exp_dd_pack, cexp_dd1, &
                                             cexp_dd2_at0, cexp_dd2, cexp_dd3
    use testing, only: test_error, unit_test, new_unittest, check, same_bits
    implicit none
    private

    public :: collect_divided_differences

    !> Tolerances: real results to a few ulps; complex ones relative, or absolute on the scale
    !> of the largest |e^x| over the nodes.
    real(dp), parameter :: rtol_real = 1.0e-15_dp
    real(dp), parameter :: rtol_cplx = 1.0e-15_dp
    real(dp), parameter :: atol_cplx = 5.0e-16_dp

    ! real e[a, b]: a, b, e[a, b]
    integer, parameter :: n_r1 = 12
    real(dp), parameter :: r1(3, n_r1) = reshape([ &
        0.0_dp, 0.0_dp, &
        1.0e0_dp, &
        1.0e-12_dp, 0.0_dp, &
        1.0000000000005e0_dp, &
        0.3_dp, 0.29999_dp, &
        1.3498520583044627928e0_dp, &
        0.49_dp, 0.0_dp, &
        1.2904412652150591165e0_dp, &
        0.5_dp, 0.0_dp, &
        1.2974425414002562937e0_dp, &
        0.51_dp, 0.0_dp, &
        1.3044925391095810032e0_dp, &
        -3.0_dp, 2.0_dp, &
        1.4678538061125572569e0_dp, &
        20.0_dp, -20.0_dp, &
        1.2129129885244756898e+7_dp, &
        -700.0_dp, -699.9_dp, &
        1.0369512340361553696e-304_dp, &
        5.0_dp, 5.000000001_dp, &
        1.4841315917678318914e+2_dp, &
        -40.0_dp, -40.2_dp, &
        3.8504798825732824179e-18_dp, &
        -1.0e-300_dp, 2.0e-300_dp, &
        1.0e0_dp], [3, n_r1])
    ! real e[x1, x2, x3]
    integer, parameter :: n_r2 = 12
    real(dp), parameter :: r2(4, n_r2) = reshape([ &
        0.0_dp, 0.0_dp, 0.0_dp, &
        5.0e-1_dp, &
        0.1_dp, 0.2_dp, 0.3_dp, &
        6.1121046656555304871e-1_dp, &
        -0.4_dp, 0.4_dp, 0.0_dp, &
        5.0670232399034255878e-1_dp, &
        1.0e-9_dp, -1.0e-9_dp, 0.0_dp, &
        5.0000000000000000004e-1_dp, &
        2.0_dp, 2.0_dp, 2.0_dp, &
        3.6945280494653251136e0_dp, &
        -3.0_dp, 0.0_dp, 4.0_dp, &
        1.8689714092012401548e0_dp, &
        10.0_dp, 10.0000001_dp, -5.0_dp, &
        1.370535743685720994e+3_dp, &
        -30.0_dp, -29.5_dp, -29.0_dp, &
        7.876110757543294097e-14_dp, &
        0.0_dp, 0.5_dp, 0.9999999_dp, &
        8.4167854245329357347e-1_dp, &
        0.0_dp, 0.5_dp, 1.0000001_dp, &
        8.4167860578186392826e-1_dp, &
        0.9_dp, -0.05_dp, 0.9_dp, &
        9.1772772182035073509e-1_dp, &
        -600.0_dp, -601.0_dp, -599.5_dp, &
        1.1755780594973494441e-261_dp], [4, n_r2])
    ! real pack: p, c, y, e[p, c, c + y], e[p, c, c - y], e[p, c, c + y, c - y]
    integer, parameter :: n_rp = 10
    real(dp), parameter :: rp(6, n_rp) = reshape([ &
        0.1_dp, 0.0_dp, 0.2_dp, &
        5.53046100443729218e-1_dp, &
        4.8454315382128513743e-1_dp, &
        1.7125736655611019193e-1_dp, &
        3.0_dp, 0.0_dp, 1.0_dp, &
        2.3217819063017553391e0_dp, &
        1.4324312705584995588e0_dp, &
        4.4467531787162789017e-1_dp, &
        -5.0_dp, 0.0_dp, 0.3_dp, &
        1.8255539899116240917e-1_dp, &
        1.4155039442427465451e-1_dp, &
        6.83416742781462603e-2_dp, &
        0.5_dp, 0.0_dp, 2.0_dp, &
        1.2647236720433792133e0_dp, &
        3.4604407320742505586e-1_dp, &
        2.2966989970898853936e-1_dp, &
        0.2_dp, -0.1_dp, 0.0_dp, &
        5.0126794126024876467e-1_dp, &
        5.0126794126024876467e-1_dp, &
        1.6283077414089659296e-1_dp, &
        1.0_dp, 1.0_dp, 0.25_dp, &
        1.4798507502085573109e0_dp, &
        1.2526183242942518724e0_dp, &
        4.5446485182861087696e-1_dp, &
        -40.0_dp, 2.0_dp, 5.0_dp, &
        4.631338096995493476e0_dp, &
        3.4916862135004346567e-2_dp, &
        4.5964212348604891295e-1_dp, &
        0.0_dp, 0.0_dp, 1.0e-8_dp, &
        5.0000000166666667083e-1_dp, &
        4.999999983333333375e-1_dp, &
        1.666666666666666675e-1_dp, &
        -0.7_dp, 0.0_dp, 0.45_dp, &
        4.7282792698206336047e-1_dp, &
        3.444276897891171643e-1_dp, &
        1.4266693021438465889e-1_dp, &
        6.0_dp, -3.0_dp, 4.0_dp, &
        8.8305531825369355724e0_dp, &
        3.4467439081620689099e0_dp, &
        6.7297615929685833281e-1_dp], [6, n_rp])
    ! complex e[x, y]: x, y, e[x, y]
    integer, parameter :: n_c1 = 8
    complex(dp), parameter :: c1(3, n_c1) = reshape([ &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.0e0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 1.0e-10_dp, dp), &
        cmplx(0.0_dp, -1.0e-10_dp, dp), &
        cmplx(1.0e0_dp, 0.0_dp, dp), &
        cmplx(-0.3_dp, 2.0_dp, dp), &
        cmplx(-0.3_dp, -2.0_dp, dp), &
        cmplx(3.3681205090573303639e-1_dp, 0.0_dp, dp), &
        cmplx(-5.0_dp, 30.0_dp, dp), &
        cmplx(-5.0_dp, 31.0_dp, dp), &
        cmplx(3.934920476735934222e-3_dp, -5.1241474308307768677e-3_dp, dp), &
        cmplx(0.5_dp, 0.5_dp, dp), &
        cmplx(0.50000001_dp, 0.5_dp, dp), &
        cmplx(1.4468890438186144014e0_dp, 7.9043908716581036094e-1_dp, dp), &
        cmplx(-700.0_dp, 1.0_dp, dp), &
        cmplx(-699.0_dp, 0.0_dp, dp), &
        cmplx(1.4885402671421753384e-304_dp, 6.5887709402569017047e-305_dp, dp), &
        cmplx(-20.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 3.0_dp, dp), &
        cmplx(-4.7375281049027823785e-2_dp, 1.4162292560347534673e-2_dp, dp), &
        cmplx(0.0_dp, 6.283185307179586_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(-3.8981718325193755985e-17_dp, 4.7738836572212254371e-33_dp, dp)], [3, n_c1])
    ! complex e[x, y, 0]: x, y, e[x, y, 0]
    integer, parameter :: n_c20 = 9
    complex(dp), parameter :: c20(3, n_c20) = reshape([ &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(5.0e-1_dp, 0.0_dp, dp), &
        cmplx(0.3_dp, 0.4_dp, dp), &
        cmplx(0.3_dp, -0.4_dp, dp), &
        cmplx(6.0377015731292583592e-1_dp, 0.0_dp, dp), &
        cmplx(-2.0_dp, 5.0_dp, dp), &
        cmplx(-2.0_dp, -5.0_dp, dp), &
        cmplx(3.4949000452152324325e-2_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 1.0e-9_dp, dp), &
        cmplx(0.0_dp, -1.0e-9_dp, dp), &
        cmplx(4.9999999999999999996e-1_dp, 0.0_dp, dp), &
        cmplx(-10.0_dp, 0.0_dp, dp), &
        cmplx(-10.0_dp, 1.0e-7_dp, dp), &
        cmplx(9.9950060077261256767e-3_dp, 9.9723060428448828186e-11_dp, dp), &
        cmplx(0.0_dp, 0.9_dp, dp), &
        cmplx(0.0_dp, -0.9_dp, dp), &
        cmplx(4.671481873201673361e-1_dp, 0.0_dp, dp), &
        cmplx(-5.0e-8_dp, 9.98749217771909e-7_dp, dp), &
        cmplx(-5.0e-8_dp, -9.98749217771909e-7_dp, dp), &
        cmplx(4.9999998333329208333e-1_dp, 0.0_dp, dp), &
        cmplx(1.0_dp, 0.0_dp, dp), &
        cmplx(-1.5_dp, 0.2_dp, dp), &
        cmplx(4.7923937785169729237e-1_dp, 2.2658829160763391525e-2_dp, dp), &
        cmplx(-2.0_dp, 39.949968710876355_dp, dp), &
        cmplx(0.0_dp, 0.5_dp, dp), &
        cmplx(-4.2846490303583093114e-3_dp, 2.442173264172273441e-2_dp, dp)], [3, n_c20])
    ! complex e[a, b, c]: a, b, c, e[a, b, c]
    integer, parameter :: n_c2 = 8
    complex(dp), parameter :: c2(4, n_c2) = reshape([ &
        cmplx(-5.0e-8_dp, 9.98749217771909e-7_dp, dp), &
        cmplx(-5.0e-8_dp, -9.98749217771909e-7_dp, dp), &
        cmplx(0.0_dp, 0.5_dp, dp), &
        cmplx(4.8966973597889911112e-1_dp, 8.2297843517134386077e-2_dp, dp), &
        cmplx(-0.015_dp, 0.2996247653315727_dp, dp), &
        cmplx(-0.015_dp, -0.2996247653315727_dp, dp), &
        cmplx(0.0_dp, 0.5_dp, dp), &
        cmplx(4.8110539698507387363e-1_dp, 8.1313464552889872346e-2_dp, dp), &
        cmplx(-0.25_dp, 4.993746088859544_dp, dp), &
        cmplx(-0.25_dp, -4.993746088859544_dp, dp), &
        cmplx(0.0_dp, 0.5_dp, dp), &
        cmplx(2.8457545739854343171e-2_dp, 2.2110005879155888826e-2_dp, dp), &
        cmplx(-10.0_dp, 199.74984355438178_dp, dp), &
        cmplx(-10.0_dp, -199.74984355438178_dp, dp), &
        cmplx(0.0_dp, 0.5_dp, dp), &
        cmplx(2.1942460804431958232e-5_dp, 1.1980230472845709231e-5_dp, dp), &
        cmplx(-300.0_dp, 10.0_dp, dp), &
        cmplx(-300.0_dp, -10.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.1098779134295227525e-5_dp, 0.0_dp, dp), &
        cmplx(2.0_dp, 1.0_dp, dp), &
        cmplx(2.0_dp, 1.0_dp, dp), &
        cmplx(2.0_dp, 1.0_dp, dp), &
        cmplx(1.9961620242206357133e0_dp, 3.1088381561839841021e0_dp, dp), &
        cmplx(0.0_dp, 0.7_dp, dp), &
        cmplx(0.0_dp, -0.7_dp, dp), &
        cmplx(0.0_dp, 0.7_dp, dp), &
        cmplx(4.6015549088406504327e-1_dp, 1.1104913891688688681e-1_dp, dp), &
        cmplx(-1.0_dp, 0.0_dp, dp), &
        cmplx(3.0_dp, 0.0_dp, dp), &
        cmplx(0.5_dp, 0.5_dp, dp), &
        cmplx(1.6060050395318546102e0_dp, 2.1781639556812149012e-1_dp, dp)], [4, n_c2])
    ! complex e[x1, x2, x3, x4]: x1, x2, x3, x4, e[x1, x2, x3, x4]
    integer, parameter :: n_c3 = 11
    complex(dp), parameter :: c3(5, n_c3) = reshape([ &
        cmplx(-5.0e-9_dp, 9.987492177719089e-8_dp, dp), &
        cmplx(-5.0e-9_dp, -9.987492177719089e-8_dp, dp), &
        cmplx(6.999999999999999e-9_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.6666666654166658399e-1_dp, 0.0_dp, dp), &
        cmplx(-5.0e-9_dp, 9.987492177719089e-8_dp, dp), &
        cmplx(-5.0e-9_dp, -9.987492177719089e-8_dp, dp), &
        cmplx(-3.0e-8_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.666666649999999275e-1_dp, 0.0_dp, dp), &
        cmplx(-0.020000000000000004_dp, 0.3994996871087636_dp, dp), &
        cmplx(-0.020000000000000004_dp, -0.3994996871087636_dp, dp), &
        cmplx(0.027999999999999997_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.6486028763976669068e-1_dp, 0.0_dp, dp), &
        cmplx(-0.020000000000000004_dp, 0.3994996871087636_dp, dp), &
        cmplx(-0.020000000000000004_dp, -0.3994996871087636_dp, dp), &
        cmplx(-0.12000000000000002_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.5888496837781262755e-1_dp, 0.0_dp, dp), &
        cmplx(-0.15000000000000002_dp, 2.9962476533157267_dp, dp), &
        cmplx(-0.15000000000000002_dp, -2.9962476533157267_dp, dp), &
        cmplx(0.20999999999999996_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.0613424889458669678e-1_dp, 0.0_dp, dp), &
        cmplx(-0.15000000000000002_dp, 2.9962476533157267_dp, dp), &
        cmplx(-0.15000000000000002_dp, -2.9962476533157267_dp, dp), &
        cmplx(-0.9_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(7.765072626670801065e-2_dp, 0.0_dp, dp), &
        cmplx(-2.5_dp, 49.937460888595446_dp, dp), &
        cmplx(-2.5_dp, -49.937460888595446_dp, dp), &
        cmplx(3.5_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(3.626141987891841814e-3_dp, 0.0_dp, dp), &
        cmplx(-2.5_dp, 49.937460888595446_dp, dp), &
        cmplx(-2.5_dp, -49.937460888595446_dp, dp), &
        cmplx(-15.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(2.6751199463388802781e-5_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(1.6666666666666666667e-1_dp, 0.0_dp, dp), &
        cmplx(0.2_dp, 0.1_dp, dp), &
        cmplx(0.2_dp, -0.1_dp, dp), &
        cmplx(0.2_dp, 0.1_dp, dp), &
        cmplx(-0.1_dp, 0.0_dp, dp), &
        cmplx(1.8897799398243381799e-1_dp, 4.7952126467725619022e-3_dp, dp), &
        cmplx(-60.0_dp, 3.0_dp, dp), &
        cmplx(-60.0_dp, -3.0_dp, dp), &
        cmplx(1.0_dp, 0.0_dp, dp), &
        cmplx(0.0_dp, 0.0_dp, dp), &
        cmplx(4.5167681919038375571e-4_dp, 0.0_dp, dp)], [5, n_c3])


contains

    subroutine collect_divided_differences(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('real e[a, b] vs mpmath, symmetric', test_real_dd1), &
                 new_unittest('real e[x1, x2, x3] vs mpmath, any order', test_real_dd2), &
                 new_unittest('real pack e[p, c, c +- y], e[p, c, c + y, c - y]', test_real_pack), &
                 new_unittest('real limits: repeated nodes, Taylor near 0', test_real_limits), &
                 new_unittest('complex e[x, y] and e^y vs mpmath', test_complex_dd1), &
                 new_unittest('complex e[x, y, 0] vs mpmath', test_complex_dd2_at0), &
                 new_unittest('complex e[a, b, c] vs mpmath, order, conjugates', &
                              test_complex_dd2), &
                 new_unittest('complex e[x1..x4] vs mpmath, order, conjugates', test_complex_dd3), &
                 new_unittest('real and complex families agree on real nodes', test_families)]
    end subroutine collect_divided_differences

    subroutine test_real_dd1(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: a, b, y
        integer :: i
        do i = 1, n_r1
            a = r1(1, i)
            b = r1(2, i)
            y = exp_dd1(a, exp(a), b, exp(b))
            call check(error, y, r1(3, i), rtol=rtol_real, message='e[a, b], case '//istr(i))
            if (allocated(error)) return
            call check(error, same_bits(exp_dd1(b, exp(b), a, exp(a)), y), &
                       'e[b, a] /= e[a, b], case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_real_dd1

    subroutine test_real_dd2(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x(3), e(3), y
        integer :: i, k, perm(3, 6)
        perm = reshape([1, 2, 3, 1, 3, 2, 2, 1, 3, 2, 3, 1, 3, 1, 2, 3, 2, 1], [3, 6])
        do i = 1, n_r2
            x = r2(1:3, i)
            e = exp(x)
            y = exp_dd2(x(1), e(1), x(2), e(2), x(3), e(3))
            call check(error, y, r2(4, i), rtol=rtol_real, message='e[x1, x2, x3], case '//istr(i))
            if (allocated(error)) return
            do k = 2, 6
                associate (p => perm(:, k))
                    call check(error, same_bits(exp_dd2(x(p(1)), e(p(1)), x(p(2)), e(p(2)), &
                                                        x(p(3)), e(p(3))), y), &
                               'node order changes e[x1, x2, x3], case '//istr(i))
                end associate
                if (allocated(error)) return
            end do
        end do
    end subroutine test_real_dd2

    subroutine test_real_pack(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: p, c, y, dplus, dminus, d3
        integer :: i
        do i = 1, n_rp
            p = rp(1, i)
            c = rp(2, i)
            y = rp(3, i)
            call exp_dd_pack(p, exp(p), c, exp(c), y, exp(y), dplus, dminus, d3)
            call check(error, dplus, rp(4, i), rtol=rtol_real, message='dplus, case '//istr(i))
            if (allocated(error)) return
            call check(error, dminus, rp(5, i), rtol=rtol_real, message='dminus, case '//istr(i))
            if (allocated(error)) return
            call check(error, d3, rp(6, i), rtol=rtol_real, message='d3, case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_real_pack

    !> e[x, x] = e^x and e[x, x, x] = e^x/2 exactly as limits; near 0 the quotient form
    !> (e^h - 1)/h is cancellation-prone, the result must still be 1 + h/2 + h^2/6.
    subroutine test_real_limits(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: x, h, dplus, dminus, d3, ref, term
        integer :: i, k
        do i = -8, 8
            x = 7.3_dp * real(i, dp)
            call check(error, exp_dd1(x, exp(x), x, exp(x)), exp(x), rtol=0.0_dp, &
                       message='e[x, x], x = '//istr(i))
            if (allocated(error)) return
            call check(error, exp_dd2(x, exp(x), x, exp(x), x, exp(x)), 0.5_dp * exp(x), &
                       rtol=rtol_real, message='e[x, x, x], x = '//istr(i))
            if (allocated(error)) return
            call exp_dd_pack(x, exp(x), x, exp(x), 0.0_dp, 1.0_dp, dplus, dminus, d3)
            call check(error, [dplus, dminus, d3], exp(x) * [0.5_dp, 0.5_dp, 1.0_dp / 6.0_dp], &
                       rtol=rtol_real, message='pack at one node, x = '//istr(i))
            if (allocated(error)) return
        end do
        do i = 1, 15
            ! e[h, 0] = sum_k h^k/(k + 1)!, summed upwards (12 terms: below 1e-20 for h <= 0.1)
            h = 10.0_dp**(-i)
            ref = 0.0_dp
            term = 1.0_dp
            do k = 1, 12
                ref = ref + term
                term = term * h / real(k + 1, dp)
            end do
            call check(error, exp_dd1(h, exp(h), 0.0_dp, 1.0_dp), ref, rtol=rtol_real, &
                       message='e[h, 0], h = 1e-'//istr(i))
            if (allocated(error)) return
            ! e[-h, 0] = (1 - e^-h)/h = e^-h e[h, 0]
            call check(error, exp_dd1(-h, exp(-h), 0.0_dp, 1.0_dp), exp(-h) * ref, &
                       rtol=rtol_real, message='e[-h, 0], h = 1e-'//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_real_limits

    subroutine test_complex_dd1(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: e, ey
        integer :: i
        do i = 1, n_c1
            call cexp_dd1(c1(1, i), c1(2, i), e, ey)
            call check_c(error, e, c1(3, i), node_scale(c1(1:2, i)), 'e[x, y], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, ey, exp(c1(2, i)), abs(exp(c1(2, i))), 'e^y, case '//istr(i))
            if (allocated(error)) return
            call cexp_dd1(c1(2, i), c1(1, i), e, ey)
            call check_c(error, e, c1(3, i), node_scale(c1(1:2, i)), 'e[y, x], case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_complex_dd1

    subroutine test_complex_dd2_at0(error)
        type(test_error), allocatable, intent(out) :: error
        integer :: i
        do i = 1, n_c20
            call check_c(error, cexp_dd2_at0(c20(1, i), c20(2, i)), c20(3, i), &
                         node_scale([c20(1:2, i), (0.0_dp, 0.0_dp)]), 'e[x, y, 0], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd2_at0(c20(2, i), c20(1, i)), c20(3, i), &
                         node_scale([c20(1:2, i), (0.0_dp, 0.0_dp)]), 'e[y, x, 0], case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_complex_dd2_at0

    subroutine test_complex_dd2(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: x(3), e
        real(dp) :: sc
        integer :: i
        do i = 1, n_c2
            x = c2(1:3, i)
            sc = node_scale(x)
            e = cexp_dd2(x(1), x(2), x(3))
            call check_c(error, e, c2(4, i), sc, 'e[a, b, c], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd2(x(3), x(1), x(2)), c2(4, i), sc, &
                         'e[c, a, b], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd2(x(2), x(3), x(1)), c2(4, i), sc, &
                         'e[b, c, a], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd2(conjg(x(1)), conjg(x(2)), conjg(x(3))), conjg(c2(4, i)), &
                         sc, 'conjugate nodes, case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_complex_dd2

    subroutine test_complex_dd3(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: x(4), e
        real(dp) :: sc
        integer :: i
        do i = 1, n_c3
            x = c3(1:4, i)
            sc = node_scale(x)
            e = cexp_dd3(x(1), x(2), x(3), x(4))
            call check_c(error, e, c3(5, i), sc, 'e[x1..x4], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd3(x(4), x(2), x(1), x(3)), c3(5, i), sc, &
                         'e[x4, x2, x1, x3], case '//istr(i))
            if (allocated(error)) return
            call check_c(error, cexp_dd3(conjg(x(1)), conjg(x(2)), conjg(x(3)), conjg(x(4))), &
                         conjg(c3(5, i)), sc, 'conjugate nodes, case '//istr(i))
            if (allocated(error)) return
        end do
    end subroutine test_complex_dd3

    !> On real nodes the complex family gives the real family's values (to rounding), and
    !> cexp_dd2 with a node at 0 is cexp_dd2_at0.
    subroutine test_families(error)
        type(test_error), allocatable, intent(out) :: error
        complex(dp) :: z(3)
        real(dp) :: x(3)
        integer :: i
        do i = 1, n_r2
            x = r2(1:3, i)
            if (maxval(abs(x)) > 100.0_dp) cycle
            z = cmplx(x, 0.0_dp, dp)
            call check_c(error, cexp_dd2(z(1), z(2), z(3)), &
                         cmplx(exp_dd2(x(1), exp(x(1)), x(2), exp(x(2)), x(3), exp(x(3))), 0.0_dp, &
                               dp), node_scale(z), 'real nodes, case '//istr(i))
            if (allocated(error)) return
        end do
        do i = 1, n_c20
            call check_c(error, cexp_dd2(c20(1, i), c20(2, i), (0.0_dp, 0.0_dp)), &
                         cexp_dd2_at0(c20(1, i), c20(2, i)), &
                         node_scale([c20(1:2, i), (0.0_dp, 0.0_dp)]), 'e[x, y, 0], case '//istr(i))
            if (allocated(error)) return
        end do
        ! e[2 pi i k, 0] = 0: a complex zero, reached to rounding (absolute)
        call check_c(error, cexp_dd2(cmplx(0.0_dp, 2.0_dp * pi, dp), &
                                     cmplx(0.0_dp, 4.0_dp * pi, dp), (0.0_dp, 0.0_dp)), &
                     (0.0_dp, 0.0_dp), 1.0_dp, 'e[2 pi i, 4 pi i, 0]')
    end subroutine test_families

    ! ---------------------------------------------------------------- helpers

    !> |got - ref| <= rtol_cplx |ref| + atol_cplx scale, scale = the largest |e^x| over the
    !> nodes (the divided difference is an average of e^x over their hull: where it has a
    !> complex zero only absolute accuracy on that scale is meaningful).
    subroutine check_c(error, got, ref, sc, message)
        type(test_error), allocatable, intent(inout) :: error
        complex(dp), intent(in) :: got, ref
        real(dp), intent(in) :: sc
        character(len=*), intent(in) :: message
        character(len=200) :: buf
        if (abs(got - ref) <= rtol_cplx * abs(ref) + atol_cplx * sc) return
        write(buf, '(a, 2es24.16, a, 2es24.16, a, es10.3)') 'got ', got, ' expected ', ref, &
            ' abs.diff ', abs(got - ref)
        call check(error, .false., message//': '//trim(buf))
    end subroutine check_c

    pure function node_scale(x) result(s)
        complex(dp), intent(in) :: x(:)
        real(dp) :: s
        s = exp(maxval(real(x, dp)))
    end function node_scale

    !> An integer as text for messages.
    pure function istr(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=12) :: buf
        write(buf, '(i0)') i
        s = trim(buf)
    end function istr

end module test_divided_differences
