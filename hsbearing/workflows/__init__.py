"""Generic workflows over any bearing system: sweeps (process pool or dask), two-key maps,
bundled studies and warm starts."""
