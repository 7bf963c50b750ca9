"""``--solve-for growth`` (``--layer K``) without ``--component`` varies g I: where the
file's layer grows anisotropically, the command says, once it has run, that this growth was
replaced (check round 29: the README's bilayer curve dropped the file's hoop growth
(1, 1.2, 1) without a word). Bad input found after the control still gets its one line."""

from electrogrowth.cli.app import main

ANISOTROPIC = (
    "length = 1.0\nstretch = 1.0\n[[layers]]\nouter_radius = 1.3\ngrowth = [1.0, 1.1, 1.0]\n"
)


def test_an_isotropic_control_over_an_anisotropic_layer_says_so(tmp_path, capsys):
    tube = tmp_path / "aniso.toml"
    tube.write_text(ANISOTROPIC)
    argv = ["critical", "--tube", str(tube), "--solve-for", "growth", "--mode", "1", "1"]
    assert main([*argv, "--json"]) == 0
    err = capsys.readouterr().err
    assert "growth varies layer 1's growth isotropically" in err
    assert "replacing its (1, 1.1, 1)" in err
    assert main([*argv, "--rtol", "1e-30"]) == 2  # refused after the control: one line
    assert capsys.readouterr().err.count("\n") == 1
    axial = ["critical", "--tube", str(tube), "--solve-for", "growth", "--component", "z"]
    assert main([*axial, "--mode", "1", "1", "--json"]) == 0  # one component alone: no note
    assert "warning" not in capsys.readouterr().err
