! f2py thin layer for seispulse_sdof_pulse (placeholder; issue 6).
subroutine sdof_pulse_placeholder()
end subroutine sdof_pulse_placeholder
