
### paper

paper-unavailable = la démo de cette figure n'est pas disponible
paper-figure = Figure { $number }
paper-section = Section { $number }
paper-section-figure = Section { $section }, figure { $figure }
paper-near-agrees = La démo calcule { $computed }, conforme à l'arrondi près à la valeur de l'article, { $claimed } (tolérance ±{ $tolerance }).
paper-near-differs = La démo calcule { $computed }, et non la valeur de l'article, { $claimed } (tolérance ±{ $tolerance }).
paper-below-agrees = La démo calcule { $computed }, soit moins que la borne de { $bound } donnée par l'article.
paper-below-differs = La démo calcule { $computed }, soit plus que la borne de { $bound } donnée par l'article.
paper-range = { $low } à { $high }
paper-range-agrees = La démo calcule de { $low } à { $high }, comme le dit l'article.
paper-range-differs = La démo calcule de { $low } à { $high }, et non l'intervalle de l'article.
paper-peak = Le maximum de |H(r)| trouvé par recherche se situe en r = { $found }, là où la formule donne { $formula }.
paper-slope = Sur le pas de l'article, h = { $step }, et cinq divisions par deux (jusqu'à { $smallest }), la pente ajustée vaut { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Réponse libre du quart de véhicule (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) pour les réglages confort, performance, critique et suramorti.
paper-exhibit-fig1b = Temps d'établissement en fonction du taux d'amortissement, avec son minimum.
paper-exhibit-fig2a = Courant dans le circuit RLC série (L = 0,5 H, C = 20 mF, V₀ = 12 V) lorsque la résistance parcourt les régimes.
paper-exhibit-fig2b = Tension aux bornes du condensateur du même circuit.
paper-exhibit-fig3a = Module de la réponse en fréquence pour une famille de taux d'amortissement.
paper-exhibit-fig3b = Phase de la réponse en fréquence.
paper-exhibit-fig4a = Euler et RK4 comparés à la réponse exacte d'un oscillateur faiblement amorti (ζ = 0,05, ωₙ = 2 rad/s) avec h = 0,3 s.
paper-exhibit-fig4b = Erreur maximale en fonction du pas en axes log–log, avec les pentes.
paper-exhibit-fig5 = Une équation, de nombreuses machines : systèmes mécaniques, électriques et autres régis par la même équation a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = L'analogie mécanique–électrique : masse ↔ inductance, amortisseur ↔ résistance, ressort ↔ 1/capacité.
paper-exhibit-table2 = Les régimes d'amortissement : condition, racines, comportement et exemples.
paper-exhibit-table3 = Les méthodes d'intégration comparées : erreur, ordre et stabilité pour un même pas.
paper-claim-fig1-zeta-optimum = Un taux d'amortissement d'environ 0,7 donne le temps d'établissement le plus court (bande de 5 %).
paper-claim-sec3-natural-frequency = La pulsation propre du quart de véhicule est d'environ 8,9 rad/s (environ 1,4 Hz).
paper-claim-sec4-critical-resistance = Le circuit est en amortissement critique pour R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 pour ζ = 0,05.
paper-claim-fig3-q-factor-light = Q = 50 pour ζ = 0,01.
paper-claim-sec5-peak-frequency = La réponse culmine à ω = ωₙ√(1 − 2ζ²), juste en dessous de ωₙ (vérifié pour ζ = 0,1).
paper-claim-fig4-euler-error = Avec h = 0,3 s, l'erreur maximale d'Euler est d'environ 0,08.
paper-claim-fig4-rk4-error = Avec h = 0,3 s, l'erreur maximale de RK4 est inférieure à 0,001.
paper-claim-fig4-euler-slope = L'erreur d'Euler décroît avec une pente ≈ 1 sur le graphe log–log.
paper-claim-sec7-mass-tolerance = Une incertitude de ±10 % sur la masse suspendue fait passer ζ = 1,0 à une valeur comprise entre 0,91 et 1,10.
paper-claim-fig1-zeta-optimum-context = Pour une bande de 2 %, le ζ qui s'établit le plus vite est plutôt { $value }.
paper-claim-sec3-natural-frequency-context = En hertz : fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler est instable avec ce pas : |1 + hλ| = { $value } par pas, donc son erreur croît sans limite.
paper-claim-fig4-rk4-error-context = RK4 est stable avec ce pas (|R(hλ)| = { $value } par pas), mais sur toute la fenêtre son erreur dépasse la borne.
paper-claim-fig4-euler-slope-context = L'ordre ajusté sur les petits pas, où l'erreur est asymptotique, vaut { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varie comme 1/√m : une masse à ±10 % ne le déplace donc que d'environ ±5 % (ωₙ descend à { $value } à +10 %).
paper-title = L'article, vérifié
paper-summary = Zeta Lab est né d'un article sur les équations différentielles du second ordre dans les systèmes mécaniques et électriques (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Voici chacune de ses figures et chacun de ses tableaux, tracés en direct par la démo qui les reproduit, et chacun des nombres qu'il avance, vérifié : chaque affirmation montre la valeur de l'article, la valeur calculée par l'application et un verdict. Suivez un lien pour ouvrir la démo exactement dans cet état.
paper-readout-claims = affirmations vérifiées
paper-readout-confirmed = affirmations confirmées
paper-readout-differs = affirmations qui diffèrent
paper-plot-fig1a = Figure 1(a)
paper-plot-fig1b = Figure 1(b)
paper-plot-fig2a = Figure 2(a)
paper-plot-fig2b = Figure 2(b)
paper-plot-fig3a = Figure 3(a)
paper-plot-fig3b = Figure 3(b)
paper-plot-fig4a = Figure 4(a)
paper-plot-fig4b = Figure 4(b)
paper-plot-fig5 = Figure 5
paper-plot-table1 = Tableau 1
paper-plot-table2 = Tableau 2
paper-plot-table3 = Tableau 3
