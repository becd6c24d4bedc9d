//! Optics for the global terms k_r·I_r and k_t·I_t: mirror reflection, refraction by Snell's law
//! (スネルの法則 n₁ sin θ₁ = n₂ sin θ₂) with total internal reflection, and Fresnel reflectance
//! (exact for dielectrics, and Schlick's approximation).
