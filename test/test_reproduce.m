## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Integration test: a reduced `make reproduce` (QUICK=1: small images, few
## samples) into a scratch folder, once on ../shared/data/merl-proxy (skipped
## when absent; with the reduced study and one more method, inplane_ggx, a
## GGX fit beside the Lafortune fits) and once with no MERL files (the
## built-in stand-ins); report.md and summary.json must
## exist and hold finite numbers, and a second run must redo nothing.
## Run by `make check` (which sets LAFORTUNE_TOP).

%!function __reproduce (use_proxy, mesh = "", extra = "")
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "Makefile"), "file") == 2, "run from the project's top folder");
%! out = tempname ();
%! proxy = getenv ("MERL_PROXY_DIR");
%! if (use_proxy && (isempty (proxy) || ! isfolder (proxy)))
%!   printf ("skipped: no ../shared/data/merl-proxy (the stand-in run is tested below)\n");
%!   return;
%! endif
%! if (! use_proxy)
%!   proxy = fullfile (out, "no-merl-files");
%! endif
%! unwind_protect
%!   cmd = sprintf ("make --no-print-directory -C '%s' reproduce QUICK=1 RESULTS='%s' MERL_DIR='%s' MESH='%s' %s 2>&1",
%!                  top, out, proxy, mesh, extra);
%!   [st, txt] = system (cmd);
%!   if (st != 0)
%!     printf ("%s\n", txt);
%!   endif
%!   assert (st, 0);
%!   rep = fileread (fullfile (out, "report.md"));
%!   ## the first lines say which data was used
%!   head = strjoin (strsplit (rep, "\n")(1:4), "\n");
%!   if (use_proxy)
%!     assert (! isempty (regexp (head, "green-metallic-paint.*neural-network reconstruction")));
%!   else
%!     assert (! isempty (regexp (head, "green-metallic-paint.*no MERL file found.*built-in stand-in")));
%!   endif
%!   assert (! isempty (strfind (rep, "| green-metallic-paint | 2 | 31.44 dB |")));
%!   assert (! isempty (strfind (rep, "## The fits as a viewer sees them: FLIP and colour difference")));
%!   assert (! isempty (regexp (rep, "\\| red-plastic \\| scene \\(for the scene's light\\) \\| 3 \\| [0-9.]+ / [0-9.]+ \\| 0\\.[0-9]{4} / 0\\.[0-9]{4} \\|")));
%!   ## held-out verdicts: every fit under the lights of JUDGE, apart from the
%!   ## in-sample scores
%!   assert (! isempty (strfind (rep, "## Held-out verdicts: every fit in light it was not made for")));
%!   assert (! isempty (regexp (rep, ["\\| red-plastic \\| in-plane \\(the paper's method\\) \\| 2 \\| 0\\.\\d{4} \\| " ...
%!                                    "0\\.\\d{4} \\| 0\\.\\d{4} \\| 0\\.\\d{4} \\| \\*\\*0\\.\\d{4}\\*\\* \\|"])), rep);
%!   assert (! isempty (strfind (rep, "in-sample")));
%!   ## the best model of each material: Lafortune's, the one model of MODELS,
%!   ## or, in the run with the extra method inplane_ggx, Lafortune's or GGX
%!   ## or the two tied (within the material's noise floor)
%!   assert (! isempty (strfind (rep, "## The best model")));
%!   if (isempty (extra))
%!     assert (! isempty (regexp (rep, ["\\| red-plastic \\| 3 \\| 0\\.\\d{4} \\((inplane|general|scene)\\) \\| " ...
%!                                      "\\*\\*lafortune\\*\\* \\|"])), rep);
%!   else
%!     assert (! isempty (regexp (rep, ["\\| red-plastic \\| 3 \\| 0\\.\\d{4} \\((inplane|hemisphere|scene)\\) \\| " ...
%!                                      "0\\.\\d{4} \\(inplane_ggx\\) \\| \\*\\*(lafortune|ggx|tie: (lafortune|ggx), (lafortune|ggx))\\*\\* \\|"])), rep);
%!   endif
%!   if (! isempty (extra))
%!     ## the study, reduced: in-plane and scene tables, plain weights
%!     assert (! isempty (strfind (rep, "## Which fit looks right")));
%!     assert (! isempty (strfind (rep, "| scene | image |")));
%!     assert (exist (fullfile (out, "figures", "study-red-plastic.png"), "file") == 2);
%!     R = jsondecode (fileread (fullfile (out, "study", "red-plastic.json")));
%!     assert (numel (R.methods), 3);
%!     assert (all (isfinite ([R.methods.psnr_a])) && all (isfinite ([R.methods.psnr_b])));
%!   endif
%!   if (! isempty (mesh))
%!     ## the paper's scene: the mesh named in the settings, every fit's PSNR
%!     ## against the measured render by the same renderer
%!     assert (! isempty (strfind (rep, ["scene `mesh` (" mesh ")"])));
%!     assert (! isempty (strfind (rep, "The measured data rendered by rt_render and by POV-Ray agree to")));
%!   endif
%!   assert (isempty (regexp (rep, "NaN|Inf")));
%!   S = jsondecode (fileread (fullfile (out, "summary.json")));
%!   mths = merge (isempty (extra), {"inplane", "general", "scene"}, {"inplane", "hemisphere", "scene"});
%!   for mat = {"green_metallic_paint", "red_plastic"}
%!     s = S.materials.(mat{1});
%!     for f = [{"psnr_inplane_pov", "psnr_inplane_rt", "psnr_scene_pov", "psnr_scene_rt", "fit_rmse_inplane", ...
%!               "flip_inplane_pov", "flip_scene_pov", "flip_scene_rt", "deltae_scene_pov", "deltae_inplane_pov", ...
%!               "hue_scene_pov", ...
%!               "fit_time_inplane", "render_time_measured", "render_time_pov", "spp_psnr", "spp_time"}, ...
%!              strcat("flip_", mths, "_pov"), strcat("flip_", mths, "_heldout"), strcat("deltae_", mths, "_heldout")]
%!       v = s.(f{1});
%!       assert (isnumeric (v) && ! isempty (v) && all (isfinite (v(:))), sprintf ("%s.%s", mat{1}, f{1}));
%!     endfor
%!     assert (numel (s.psnr_inplane_pov), 3);
%!     ## more lobes never fit worse (the growing fit)
%!     assert (all (diff (s.fit_rmse_inplane) <= 1e-12));
%!     ## the recommended fit (scene table, lafortune_fit's defaults there):
%!     ## as a viewer sees it, its picture gets no worse with more lobes (FLIP
%!     ## up by 0.01 at most on QUICK's small images and table), and it looks
%!     ## closer to the measured picture than the paper's method's best
%!     assert (numel (s.flip_scene_pov), 3);
%!     assert (all (diff (s.flip_scene_pov) <= 0.01), mat2str (s.flip_scene_pov, 4));
%!     assert (all (diff (s.flip_scene_rt) <= 0.01), mat2str (s.flip_scene_rt, 4));
%!     assert (all (s.flip_scene_pov > 0 & s.flip_scene_pov < 1), mat2str (s.flip_scene_pov, 4));
%!     assert (s.flip_scene_pov(end) < min (s.flip_inplane_pov),
%!             sprintf ("%s %s", mat2str (s.flip_scene_pov, 4), mat2str (s.flip_inplane_pov, 4)));
%!     assert (s.deltae_scene_pov(end) < min (s.deltae_inplane_pov),
%!             sprintf ("%s %s", mat2str (s.deltae_scene_pov, 4), mat2str (s.deltae_inplane_pov, 4)));
%!     ## the two renderers agree on the same model
%!     assert (all (s.renderers_psnr > 30));
%!     ## the best model: the lowest held-out FLIP of every method
%!     b = S.best_model.(mat{1});
%!     f = cell2mat (cellfun (@(m) s.(["flip_" m "_heldout"])(:)', mths(:), "uniformoutput", false));
%!     if (isempty (extra))
%!       assert (b.model(:)', repmat ({"lafortune"}, 1, 3));
%!       ## the general fit: the best method under held-out light at every
%!       ## lobe count, and its held-out FLIP never rises with a lobe
%!       bm = S.heldout.best_method.(mat{1});
%!       assert (bm.method(:)', {"general", "general", "general"});
%!       assert (all (diff (s.flip_general_heldout) <= 0.002), mat2str (s.flip_general_heldout, 4));
%!     else
%!       f(end+1,:) = s.flip_inplane_ggx_heldout;
%!       assert (all (ismember (b.model, {"lafortune", "ggx"})));
%!       assert (all (isfinite (s.fit_rmse_inplane_ggx)) && all (diff (s.fit_rmse_inplane_ggx) <= 1e-12));
%!     endif
%!     assert (b.flip(:)', min (f));
%!     ## every verdict states its noise: the measured data rendered twice
%!     ## under each light (seeds s and s + 1), their FLIP the floor; the
%!     ## methods within it of the best tie (repro_tie), and the report says so
%!     J = jsondecode (fileread (fullfile (out, "judge", [strrep(mat{1}, "_", "-") ".json"])));
%!     assert (numel (J.noise_flip), 3);
%!     assert (all (isfinite (J.noise_flip) & J.noise_flip >= 0 & J.noise_flip < 1), mat2str (J.noise_flip));
%!     assert (J.noise_flip_mean, mean (J.noise_flip), 1e-12);
%!     assert (J.time_noise > 0);
%!     assert (s.heldout_noise_flip(:)', J.noise_flip(:)', 1e-12);
%!     assert (s.heldout_noise_flip_mean, J.noise_flip_mean, 1e-12);
%!     if (isempty (extra))
%!       for j = 1:3
%!         tie = mths(abs (f(:,j) - bm.flip(j)) <= J.noise_flip_mean & ! strcmp (mths(:), bm.method{j}));
%!         assert (sort (strsplit (bm.tied{j}, ", ")), sort ([bm.method(j), tie(:)']), bm.tied{j});
%!         if (! isempty (tie))
%!           pat = [sprintf("%d lobes?: tie within the noise floor %.4f: ", j, J.noise_flip_mean) "general \\("];
%!           assert (! isempty (regexp (rep, pat)), rep);
%!         endif
%!       endfor
%!     endif
%!   endfor
%!   assert (! isempty (regexp (rep, "\\| red-plastic \\| 0\\.\\d{4} \\| 0\\.\\d{4} \\| 0\\.\\d{4} \\| \\*\\*0\\.\\d{4}\\*\\* \\|")), rep);
%!   for f = {"figures/plane-red-plastic.png", "figures/renders-green-metallic-paint.png", ...
%!            "figures/fit-trace.png", "figures/spp.png", "figures/env-samples.png", "fit/red-plastic-inplane-2.json", ...
%!            "figures/heldout-red-plastic.png", "judge/red-plastic.json", "judge/red-plastic-measured.exr", ...
%!            "fit/red-plastic-inplane-2.brdf", "render/red-plastic-measured.exr"}
%!     assert (exist (fullfile (out, f{1}), "file") == 2, f{1});
%!   endfor
%!   ## incremental: a second run redoes nothing
%!   t0 = dir (fullfile (out, "report.md")).datenum;
%!   [st, txt] = system (cmd);
%!   assert (st, 0);
%!   assert (isempty (regexp (txt, "\\] (fitting|rendering|POV-Ray render|held-out light|figures)")), txt);
%!   assert (dir (fullfile (out, "report.md")).datenum, t0);
%! unwind_protect_cleanup
%!   if (strncmp (out, tempdir (), numel (tempdir ())) && isfolder (out))
%!     confirm_recursive_rmdir (false, "local");
%!     rmdir (out, "s");
%!   endif
%! end_unwind_protect
%!endfunction

%!test __reproduce (true, "", "STUDY=1 STUDY_WEIGHTS=plain STUDY_TABLES='inplane scene' METHODS='inplane hemisphere scene inplane_ggx'")  # on ../shared/data/merl-proxy
%!test __reproduce (false)   # no MERL files: the built-in stand-ins

%!test
%! ## the paper's scene, when ../shared has the Happy Buddha (100k triangles)
%! proxy = getenv ("MERL_PROXY_DIR");
%! mesh = fullfile (fileparts (proxy), "meshes", "happy-buddha.obj");
%! if (isempty (proxy) || ! exist (mesh, "file"))
%!   printf ("skipped: no happy-buddha.obj beside MERL_PROXY_DIR\n");
%! else
%!   __reproduce (true, mesh);
%! endif
