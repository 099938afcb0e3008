## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_settings ()
## Step 0 of `make reproduce` and `make database`: RESULTS/settings.json, the settings every
## later step depends on (scene, sizes, samples, data folder).  Rewritten only
## when they change, so that Make redoes exactly the steps they affect.
## @end deftypefn
function repro_settings ()
  c = repro_config ();
  ## not the folders nor the list of materials: a new material or a moved
  ## output folder must not make the other materials' steps out of date
  ## nor POV-Ray's thread count, which does not change the images
  s = rmfield (c, {"results", "data_dir", "merl_dir", "materials", "database", "pov_threads"});
  if (isempty (s.judge))
    s.judge = {};                       # jsonencode aborts Octave on an empty struct array
  endif
  txt = jsonencode (s);
  f = repro_files ("settings", c.results, "");
  if (exist (f, "file") && strcmp (fileread (f), txt))
    return;
  endif
  printf ("reproduce: settings: %s\n", txt);
  repro_save (f, txt);
endfunction
