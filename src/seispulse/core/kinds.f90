!> Working precision of seispulse. Nothing else lives here.
module seispulse_kinds
    use, intrinsic :: iso_fortran_env, only: real64, int32
    implicit none
    private

    public :: dp, ik

    integer, parameter :: dp = real64   !! working real kind (= C double)
    integer, parameter :: ik = int32    !! LAPACK/BLAS integer (LP64)

end module seispulse_kinds
