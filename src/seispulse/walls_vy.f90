!> Placeholder (issue 7, being written).
module seispulse_walls_vy
    implicit none
    private
end module seispulse_walls_vy
