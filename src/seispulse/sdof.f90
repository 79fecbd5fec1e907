!> Linear oscillator on records (placeholder; issue 6).
module seispulse_sdof
    implicit none
    private
end module seispulse_sdof
