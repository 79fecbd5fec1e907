!> Placeholder (issue 7, being written).
module seispulse_codes
    implicit none
    private
end module seispulse_codes
