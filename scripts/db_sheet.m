## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} db_sheet (@var{material})
## Gallery step of `make database` (run by repro_step, which writes @var{R}
## to RESULTS/sheet/MATERIAL.json): the material's contact sheet
## RESULTS/sheet/MATERIAL.png, one row per fit method, the measured-data
## render first and then the render of each lobe count (titled METHOD K: PSNR), all
## at the measured render's exposure.  @var{R}: @code{file} (the PNG's name,
## relative to RESULTS) and @code{exposure} (stops).
## @end deftypefn
function R = db_sheet (material)
  c = repro_config ();
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  rd = fullfile (c.results, "render");
  ref = exrread (fullfile (rd, [material "-measured.exr"]));
  fits = jsondecode (fileread (fullfile (rd, [material "-fits.json"])));
  [rgb, stops] = img_tonemap (ref, "auto");
  nm = numel (c.methods);
  nk = numel (c.lobes);
  label = struct ("inplane", "in-plane", "hemisphere", "hemisphere");
  w = 200 * (1 + nk);
  ht = round (w / (1 + nk) * c.size(1) / c.size(2) * nm + 60 * nm);
  h = figure ("visible", "off", "position", [0, 0, w, ht]);
  for i = 1:nm
    mth = c.methods{i};
    subplot (nm, 1 + nk, (i - 1) * (1 + nk) + 1);
    show (rgb, "measured");
    for j = 1:nk
      img = exrread (fullfile (rd, sprintf ("%s-%s-%d.exr", material, mth, c.lobes(j))));
      subplot (nm, 1 + nk, (i - 1) * (1 + nk) + 1 + j);
      name = mth;
      if (isfield (label, mth))
        name = label.(mth);
      endif
      show (img_tonemap (img, stops), sprintf ("%s %d: %.2f dB", name, c.lobes(j),
                                                fits.(mth)(j).psnr_pov));
    endfor
  endfor
  sd = fullfile (c.results, "sheet");
  if (! isfolder (sd))
    mkdir (sd);
  endif
  file = fullfile (sd, [material ".png"]);
  tmp = [file ".tmp.png"];
  print (h, "-dpngcairo", "-r72", tmp);
  close (h);
  [err, msg] = rename (tmp, file);
  if (err)
    error ("lafortune:unwritable", "db_sheet: cannot write '%s': %s", file, msg);
  endif
  R = struct ("file", fullfile ("sheet", [material ".png"]), "exposure", stops);
endfunction

function show (rgb, ttl)
  image (rgb);
  axis image;
  set (gca, "xtick", [], "ytick", []);
  title (ttl, "interpreter", "none");
endfunction
