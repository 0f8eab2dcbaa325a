"""Generic workflows over any bearing system: sweeps (process pool or dask), two-key maps,
bundled studies, warm starts, and the comparison of lubricants (``compare``: ``hsbearing compare``)."""
