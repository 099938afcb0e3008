## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_data (@var{material})
## Step 1 of `make reproduce`: RESULTS/data/MATERIAL.binary and its
## .source.json.  The real MERL file MERL_DIR/MATERIAL.binary when present,
## else the built-in stand-in (merl_standin).  The files are rewritten only
## when the source changed, so later steps are not redone for nothing.
## @end deftypefn
function repro_data (material)
  c = repro_config ();
  out = repro_files ("data", c.results, material);
  src_file = repro_files ("source", c.results, material);
  merl = repro_files ("merl", c.merl_dir, material);
  if (exist (merl, "file"))
    s = dir (merl);
    src = struct ("kind", "merl-file", "path", make_absolute_filename (merl),
                  "bytes", s.bytes, "modified", s.datenum,
                  "sha256", sha256_of (merl));
  else
    src = struct ("kind", "built-in-standin", "path", "",
                  "bytes", 0, "modified", 0, "sha256", "");
  endif
  if (exist (out, "file") && exist (src_file, "file"))
    old = jsondecode (fileread (src_file));
    if (strcmp (old.kind, src.kind) && strcmp (old.path, src.path) && strcmp (old.sha256, src.sha256))
      printf ("reproduce: [%s] data unchanged (%s)\n", material, describe (src));
      return;
    endif
  endif
  repro_mkdir (fileparts (out));
  if (strcmp (src.kind, "merl-file"))
    printf ("reproduce: [%s] reading %s\n", material, merl);
    b = merl_read (merl);          # validates the file
    merl_write (out, b);
  else
    printf ("reproduce: [%s] no MERL file in %s: generating the built-in stand-in\n",
            material, c.merl_dir);
    merl_write (out, merl_standin (material));
  endif
  repro_save (src_file, src);
endfunction

function s = describe (src)
  if (strcmp (src.kind, "merl-file"))
    s = src.path;
  else
    s = "built-in stand-in";
  endif
endfunction

function h = sha256_of (f)
  [st, out] = system (sprintf ("sha256sum '%s'", f));
  h = "";
  if (st == 0)
    h = strtok (out);
  endif
endfunction
