"""``--solve-for growth --layer K`` without ``--component`` varies g I: where the file's
layer K grows anisotropically, the command says that its growth is replaced (check round
29: the README's bilayer curve dropped the file's hoop growth (1, 1.2, 1) without a word)."""

from pathlib import Path

from electrogrowth.cli.app import main

BILAYER = str(Path(__file__).resolve().parents[2] / "examples" / "bilayer.toml")


def test_an_isotropic_control_over_an_anisotropic_layer_says_so(capsys):
    main(["state", "--tube", BILAYER])  # a command without the control: no note
    assert "warning" not in capsys.readouterr().err
    argv = ["critical", "--tube", BILAYER, "--solve-for", "growth", "--layer", "1"]
    assert main([*argv, "--mode", "3", "0", "--rtol", "1e-30"]) == 2  # refused after it
    err = capsys.readouterr().err
    assert "growth[1] varies layer 1's growth isotropically" in err
    assert "replacing its (1, 1.2, 1)" in err
    assert main([*argv, "--component", "theta", "--mode", "3", "0", "--rtol", "1e-30"]) == 2
    assert "isotropically" not in capsys.readouterr().err  # the hoop one alone: no note
