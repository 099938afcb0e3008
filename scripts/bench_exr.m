## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_exr: exrwrite/exrread time and file size for float32 and half
## channels, on a smooth (render-like) and a random (incompressible) RGB
## image of a few sizes; best of 3 runs.  Prints a table; not a test.
## Needs the oct-files built (make -C src).  Run: octave-cli scripts/bench_exr.m

1;
here = fileparts (mfilename ("fullpath"));
addpath (fullfile (here, "..", "src"));
addpath (fullfile (here, "..", "inst"));
if (exist ("exrwrite") != 3)
  error ("bench_exr: exrwrite.oct not found; run 'make -C src' first");
endif

sizes = [256 256; 1080 1920; 2048 2048];
reps = 3;
f = [tempname() ".exr"];
printf ("bench_exr: best of %d runs; MB/s counts the double image (H*W*3*8 bytes)\n\n", reps);
printf ("%-11s %-7s %-6s | %9s %9s | %9s %9s | %10s\n", "size", "content", "type",
        "write s", "MB/s", "read s", "MB/s", "file MB");
unwind_protect
  for s = 1:rows (sizes)
    h = sizes(s, 1);
    w = sizes(s, 2);
    [x, y] = meshgrid ((1:w) / w, (1:h) / h);
    smooth = cat (3, sin (7 * x) .^ 2, cos (5 * y) .^ 2, 4 * x .* y);
    rand ("seed", s);
    noise = rand (h, w, 3);
    mb = h * w * 3 * 8 / 2^20;
    for c = {"smooth", "random"}
      if (strcmp (c{1}, "smooth"))
        img = smooth;
      else
        img = noise;
      endif
      for t = {"float", "half"}
        tw = Inf;
        tr = Inf;
        for r = 1:reps
          t0 = tic ();
          exrwrite (f, img, t{1});
          tw = min (tw, toc (t0));
          t0 = tic ();
          back = exrread (f);
          tr = min (tr, toc (t0));
        endfor
        if (strcmp (t{1}, "float"))
          assert (isequal (back, double (single (img))));
        endif
        d = dir (f);
        printf ("%-11s %-7s %-6s | %9.3f %9.1f | %9.3f %9.1f | %10.2f\n",
                sprintf ("%dx%d", h, w), c{1}, t{1}, tw, mb / tw, tr, mb / tr,
                d.bytes / 2^20);
      endfor
    endfor
  endfor
unwind_protect_cleanup
  if (exist (f, "file"))
    unlink (f);
  endif
end_unwind_protect
