!> Elastodynamic seismic earth pressures on retaining walls (walls.md, seed 004): one
!> `use` for the Veletsos-Younan series (seispulse_walls_vy), the one-term solution and
!> its extensions (seispulse_walls_one_term) and the shared factors
!> (seispulse_walls_common).
module seispulse_walls
    use seispulse_walls_common
    use seispulse_walls_vy
    use seispulse_walls_one_term
    implicit none
    public
end module seispulse_walls
