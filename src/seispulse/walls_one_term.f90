!> Placeholder (issue 7, being written).
module seispulse_walls_one_term
    implicit none
    private
end module seispulse_walls_one_term
