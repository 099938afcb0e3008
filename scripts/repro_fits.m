## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{models} =} repro_fits (@var{c}, @var{material})
## The fits of @var{material} that the pipeline renders and judges
## (repro_render_fits, repro_judge): a struct with one field per method of
## METHODS, a cell of models indexed by lobe count (empty for a lobe count
## not in LOBES), and in make database the field @code{ngan2005}, the
## material's published 1-lobe fit (PUBLISHED, read by lafortune_ngan), when
## the table has it.
## @end deftypefn
function models = repro_fits (c, material)
  models = struct ();
  for method = c.methods
    for k = c.lobes
      models.(method{1}){k} = brdf_import ([repro_files("model", c.results, material, method{1}, k) ".json"]);
    endfor
  endfor
  pub = published (c, material);
  if (! isempty (pub))
    models.ngan2005 = {pub};
  endif
endfunction

## the published 1-lobe fit of MATERIAL from the table PUBLISHED, in make
## database (else [], also when the table has no such material or is absent)
function m = published (c, material)
  m = [];
  if (! c.database || isempty (c.published))
    return;
  endif
  if (! exist (c.published, "file"))
    printf ("reproduce: [%s] no table of published fits at %s (PUBLISHED): no baseline row\n",
            material, c.published);
    return;
  endif
  m = lafortune_ngan (c.published, material);
endfunction
