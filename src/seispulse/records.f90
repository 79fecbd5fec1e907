!> Placeholder (work in progress).
module seispulse_records
    implicit none
    private
end module seispulse_records
