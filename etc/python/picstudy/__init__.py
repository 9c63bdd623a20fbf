"""Design studies of a granular-pic case (picStudy): many variants of one base case, each a
copy with named dictionary entries rewritten, run here or on a Slurm cluster, their results
gathered into one CSV table and plots. Standard library only.

    studydict   reads system/studyDict into a Study
    foamdict    the OpenFOAM dictionary reader that keeps each entry's place in the text
    expression  the restricted arithmetic of entry values built from parameters
    design      parameter values, full factorial and Latin hypercube designs
    cases       the case copies, their rewritten entries and diffs
    runcase     one case's run and its status file
    results     what a finished case yields (function-object columns, wall time, status)
    executors   where the cases run: local processes or a Slurm job array
    report      results.csv and the plots
    cli         the picStudy command line
"""
