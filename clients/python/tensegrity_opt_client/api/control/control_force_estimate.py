from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.force_estimate_out import ForceEstimateOut
from ...models.force_estimate_request import ForceEstimateRequest
from ...types import Response


def _get_kwargs(
    *,
    body: ForceEstimateRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/control/force-estimate",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | ForceEstimateOut | None:
    if response.status_code == 200:
        response_200 = ForceEstimateOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | ForceEstimateOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ForceEstimateRequest,
) -> Response[ErrorOut | ForceEstimateOut]:
    """The tip force from measured joint angles (the arm as a force sensor)

     At a static equilibrium under a tip force only, the spring torques balance it: `grad E(q) = J(q)^T
    F` (`tensegrity_opt.estimate_tip_force`). `F` by least squares on these `n` equations; with
    `sigma_q` (the angle noise: one standard deviation, one per joint, or a covariance) by generalised
    least squares with the residual's covariance at the estimate, with the force's `covariance`, the
    chi-square test of the `n - 2` spare equations (`chi2`, `dof`, `p_value`: small when the arm is
    loaded elsewhere too) and `joint_chi2` (where such a load is). With `measured` the unmeasured angles
    are estimated too (`hidden_covariance`). Refused: angles outside the physical range or a
    configuration where the torques do not determine the force (collinear links: `q_measured`), a noise
    that is not positive or not a covariance (`sigma_q`), fewer equations than unknowns (`measured`).

    Args:
        body (ForceEstimateRequest): The tip force from measured joint angles
            (`tensegrity_opt.estimate_tip_force`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ForceEstimateOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: ForceEstimateRequest,
) -> ErrorOut | ForceEstimateOut | None:
    """The tip force from measured joint angles (the arm as a force sensor)

     At a static equilibrium under a tip force only, the spring torques balance it: `grad E(q) = J(q)^T
    F` (`tensegrity_opt.estimate_tip_force`). `F` by least squares on these `n` equations; with
    `sigma_q` (the angle noise: one standard deviation, one per joint, or a covariance) by generalised
    least squares with the residual's covariance at the estimate, with the force's `covariance`, the
    chi-square test of the `n - 2` spare equations (`chi2`, `dof`, `p_value`: small when the arm is
    loaded elsewhere too) and `joint_chi2` (where such a load is). With `measured` the unmeasured angles
    are estimated too (`hidden_covariance`). Refused: angles outside the physical range or a
    configuration where the torques do not determine the force (collinear links: `q_measured`), a noise
    that is not positive or not a covariance (`sigma_q`), fewer equations than unknowns (`measured`).

    Args:
        body (ForceEstimateRequest): The tip force from measured joint angles
            (`tensegrity_opt.estimate_tip_force`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ForceEstimateOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: ForceEstimateRequest,
) -> Response[ErrorOut | ForceEstimateOut]:
    """The tip force from measured joint angles (the arm as a force sensor)

     At a static equilibrium under a tip force only, the spring torques balance it: `grad E(q) = J(q)^T
    F` (`tensegrity_opt.estimate_tip_force`). `F` by least squares on these `n` equations; with
    `sigma_q` (the angle noise: one standard deviation, one per joint, or a covariance) by generalised
    least squares with the residual's covariance at the estimate, with the force's `covariance`, the
    chi-square test of the `n - 2` spare equations (`chi2`, `dof`, `p_value`: small when the arm is
    loaded elsewhere too) and `joint_chi2` (where such a load is). With `measured` the unmeasured angles
    are estimated too (`hidden_covariance`). Refused: angles outside the physical range or a
    configuration where the torques do not determine the force (collinear links: `q_measured`), a noise
    that is not positive or not a covariance (`sigma_q`), fewer equations than unknowns (`measured`).

    Args:
        body (ForceEstimateRequest): The tip force from measured joint angles
            (`tensegrity_opt.estimate_tip_force`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | ForceEstimateOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: ForceEstimateRequest,
) -> ErrorOut | ForceEstimateOut | None:
    """The tip force from measured joint angles (the arm as a force sensor)

     At a static equilibrium under a tip force only, the spring torques balance it: `grad E(q) = J(q)^T
    F` (`tensegrity_opt.estimate_tip_force`). `F` by least squares on these `n` equations; with
    `sigma_q` (the angle noise: one standard deviation, one per joint, or a covariance) by generalised
    least squares with the residual's covariance at the estimate, with the force's `covariance`, the
    chi-square test of the `n - 2` spare equations (`chi2`, `dof`, `p_value`: small when the arm is
    loaded elsewhere too) and `joint_chi2` (where such a load is). With `measured` the unmeasured angles
    are estimated too (`hidden_covariance`). Refused: angles outside the physical range or a
    configuration where the torques do not determine the force (collinear links: `q_measured`), a noise
    that is not positive or not a covariance (`sigma_q`), fewer equations than unknowns (`measured`).

    Args:
        body (ForceEstimateRequest): The tip force from measured joint angles
            (`tensegrity_opt.estimate_tip_force`).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | ForceEstimateOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
