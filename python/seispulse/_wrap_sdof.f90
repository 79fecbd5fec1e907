! f2py thin layer for seispulse_sdof (placeholder; issue 6).
subroutine sdof_placeholder()
end subroutine sdof_placeholder
