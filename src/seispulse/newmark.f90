!> Placeholder (work in progress).
module seispulse_newmark
    implicit none
    private
end module seispulse_newmark
