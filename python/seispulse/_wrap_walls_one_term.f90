! Placeholder (issue 7): f2py layer of seispulse_walls_one_term.
