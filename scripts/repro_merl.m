## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{b} =} repro_merl (@var{c}, @var{material})
## The MERL file of @var{material} (in @var{c}.data_dir), read by merl_read
## once per process: the steps of one material that run in one process
## (repro_material) share it.  The file is read again when its size or
## modification time has changed.
## @end deftypefn
function b = repro_merl (c, material)
  persistent last;
  file = repro_files ("merl", c.data_dir, material);
  [st, err, msg] = stat (file);
  if (err == 0 && ! isempty (last) && strcmp (last.file, file)
      && last.mtime == st.mtime && last.size == st.size)
    b = last.b;
    return;
  endif
  last = [];
  b = merl_read (file);
  if (err == 0)
    last = struct ("file", file, "mtime", st.mtime, "size", st.size, "b", b);
  endif
endfunction
