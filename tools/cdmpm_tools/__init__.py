"""cdmpm_tools - what the post-processing commands in tools/ share, so that they read runs alike and behave alike
(docs/tools.md).

  cli       the repository and its program (REPO, CDMPM); one-line errors (fail); output folders that refuse
            committed files (output_folder, add_output_arguments); running cdmpm on a scene (run_cdmpm);
  io        a run's tables and records: read_csv (probes.csv, waves.csv, hazard.csv ...), read_table (the same with
            one-line errors for a missing file or column), read_waves, read_summary, read_scene and probe_list
            (scene.resolved.json), read_asc and write_asc (ESRI ASCII grids);
  frames    particle frames (.vtu, a distributed run's .pvtu, particles.pvd): read_vtu, read_pvtu, read_frame,
            read_pvd, read_field_data, first_piece, frame_file, add_frame_arguments, read_material_frame;
  plotting  figures: pyplot (matplotlib drawing to files), save_figure, the ice and water colours, ice_mask,
            robust_range, probe_units.

No installation: a command adds its own folder, tools/, to sys.path and imports from the package:

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from cdmpm_tools.io import read_csv  # noqa: E402
"""
