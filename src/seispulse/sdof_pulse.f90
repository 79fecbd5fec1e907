!> Linear oscillator closed forms (placeholder; issue 6).
module seispulse_sdof_pulse
    implicit none
    private
end module seispulse_sdof_pulse
