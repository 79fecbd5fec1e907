! f2py layer of seispulse.records (see _wrap.f90 for the conventions).
