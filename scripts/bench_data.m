## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{file} =} bench_data (@var{name})
## The MERL-format stand-in @var{name}.binary kept beside the project, for the
## benchmarks: in MERL_PROXY_DIR, else ../shared/data/merl-proxy; "" when
## absent (the benchmark then says what it uses instead).
## @end deftypefn
function file = bench_data (name)
  pd = getenv ("MERL_PROXY_DIR");
  if (isempty (pd))
    pd = fullfile (fileparts (mfilename ("fullpath")), "..", "..", "shared", "data", "merl-proxy");
  endif
  file = fullfile (pd, [name ".binary"]);
  if (! exist (file, "file"))
    file = "";
  endif
endfunction
