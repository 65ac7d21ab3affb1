#pragma once
// The refractive index of liquid water at 20 °C: Daimon & Masumura (2007, Appl. Opt. 46, 3811), their
// four-term Sellmeier fit n² − 1 = Σ Aᵢ λ² / (λ² − Bᵢ), λ in µm, valid from 182 nm to 1129 nm
// (1.3436 at 400 nm, 1.3306 at 700 nm). The imaginary part in the visible is below 1e-8 (Hale & Querry
// 1973): a 25 µm drop absorbs less than 1e-5 of the light crossing it, so cloud drops are taken as
// non-absorbing (k = 0).
namespace aurorawall::components::glory::optics {

double waterRefractiveIndex(double wavelengthNm);

} // namespace aurorawall::components::glory::optics
