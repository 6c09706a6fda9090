"""Linear vibration models of a bearing: generic eigen, frequency and time
response tools for M q'' + C q' + K q = f (:mod:`.linear`) and the 3-DOF
outer ring / ball / inner ring model of El Had et al. 2014 (:mod:`.three_dof`)."""
from . import linear, three_dof
from .linear import ModalResult, frequency_response, modal_analysis, time_response
from .three_dof import (ThreeDofParameters, ThreeDofResult, analyse, ball_pass_response, derived_parameters,
                        source_parameters)

__all__ = ["linear", "three_dof", "ModalResult", "modal_analysis", "frequency_response", "time_response",
           "ThreeDofParameters", "ThreeDofResult", "analyse", "derived_parameters", "source_parameters",
           "ball_pass_response"]
